// SPDX-License-Identifier: MIT
#include <seamless/render/scene/scene.h>

#include <seamless/base/error.h>
#include <seamless/base/files/input_file.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <map>
#include <sstream>

namespace seamless {
namespace {

using json = nlohmann::json;

struct Reader {
    std::string file;
    double max_coordinate; // SceneLimits::max_coordinate

    [[noreturn]] void fail(const std::string& field, const std::string& msg) const {
        throw InputError(file, field, msg);
    }
    double number(const json& j, const std::string& f) const {
        if (!j.is_number()) fail(f, "expected a number");
        double x = j.get<double>();
        if (!std::isfinite(x)) fail(f, "not a finite number");
        return x;
    }
    double number_in(const json& obj, const char* key, const std::string& f, double dflt, double lo,
                     double hi) const {
        auto it = obj.find(key);
        if (it == obj.end()) return dflt;
        const std::string fk = f.empty() ? key : f + "." + key;
        double x = number(*it, fk);
        if (x < lo || x > hi) {
            std::ostringstream os;
            os << "value " << x << " outside " << lo << ".." << hi;
            fail(fk, os.str());
        }
        return x;
    }
    long long integer_in(const json& obj, const char* key, const std::string& f, long long dflt,
                         long long lo, long long hi) const {
        auto it = obj.find(key);
        if (it == obj.end()) return dflt;
        const std::string fk = f.empty() ? key : f + "." + key;
        if (!it->is_number()) fail(fk, "expected an integer");
        double x = it->get<double>();
        if (!std::isfinite(x) || x != std::floor(x)) fail(fk, "expected an integer");
        if (x < static_cast<double>(lo) || x > static_cast<double>(hi))
            fail(fk, "value " + it->dump() + " outside " + std::to_string(lo) + ".." +
                         std::to_string(hi));
        return static_cast<long long>(x);
    }
    Vec3 vec3(const json& j, const std::string& f) const {
        if (!j.is_array() || j.size() != 3) fail(f, "expected [x, y, z]");
        return {number(j[0], f + "[0]"), number(j[1], f + "[1]"), number(j[2], f + "[2]")};
    }
    // A point of the world: coordinates within max_coordinate.
    Vec3 point(const json& j, const std::string& f) const {
        const Vec3 p = vec3(j, f);
        for (int k = 0; k < 3; ++k)
            if (std::abs(p[k]) > max_coordinate) {
                std::ostringstream os;
                os << "coordinate " << p[k] << " beyond the scene limit of " << max_coordinate
                   << " (docs/formats.md, Limits)";
                fail(f + "[" + std::to_string(k) + "]", os.str());
            }
        return p;
    }
    Vec3 colour(const json& j, const std::string& f) const {
        Vec3 c = vec3(j, f);
        for (int k = 0; k < 3; ++k)
            if (c[k] < 0) fail(f + "[" + std::to_string(k) + "]", "colour components must be >= 0");
        return c;
    }
};

json parse_json(const std::string& text, const std::string& file) {
    try {
        return naming_file_on_oom(file, [&] { return json::parse(text); });
    } catch (const json::parse_error& e) {
        std::string what = e.what();
        auto pos = what.find("syntax error");
        throw InputError(file, "byte " + std::to_string(e.byte),
                         "JSON " + (pos == std::string::npos ? what : what.substr(pos)));
    } catch (const json::out_of_range&) {
        throw InputError(file, "", "a number is not finite (overflows a double)");
    }
}

} // namespace

Scene load_scene(const std::filesystem::path& path, const SceneLimits& lim) {
    const std::string text = read_input_file(path, lim.max_file_bytes, "scene");
    return parse_scene(text, path.string(), path.parent_path(), lim);
}

Scene parse_scene(const std::string& text, const std::string& file,
                  const std::filesystem::path& folder, const SceneLimits& lim) {
    Reader r{file, lim.max_coordinate};
    const json root = parse_json(text, file);
    if (!root.is_object()) r.fail("", "expected a JSON object at the top level");
    Scene sc;
    sc.source = r.file;
    if (r.integer_in(root, "version", "", -1, 0, 1000000) != 1)
        r.fail("version",
               root.contains("version")
                   ? "unsupported version " + root["version"].dump() + " (this reader knows 1)"
                   : "missing");

    // Camera.
    auto cam = root.find("camera");
    if (cam == root.end()) r.fail("camera", "missing");
    if (!cam->is_object()) r.fail("camera", "expected an object");
    for (const char* key : {"eye", "look_at"})
        if (!cam->contains(key)) r.fail(std::string("camera.") + key, "missing");
    Camera& c = sc.camera;
    c.eye = r.point((*cam)["eye"], "camera.eye");
    c.look_at = r.point((*cam)["look_at"], "camera.look_at");
    if (cam->contains("up")) c.up = r.vec3((*cam)["up"], "camera.up");
    c.fov_deg = r.number_in(*cam, "fov_deg", "camera", 40, 1e-3, 179);
    c.width = static_cast<int>(r.integer_in(*cam, "width", "camera", 640, 1, lim.max_width));
    c.height = static_cast<int>(r.integer_in(*cam, "height", "camera", 480, 1, lim.max_height));
    if (norm(c.look_at - c.eye) == 0) r.fail("camera.look_at", "equals the eye point");
    if (norm(cross(c.look_at - c.eye, c.up)) == 0)
        r.fail("camera.up", "parallel to the viewing direction");

    sc.levels = static_cast<int>(r.integer_in(root, "levels", "", 16, 2, lim.max_levels));
    sc.max_depth = static_cast<int>(r.integer_in(root, "max_depth", "", 2, 0, lim.max_depth));
    if (root.contains("background")) sc.background = r.colour(root["background"], "background");
    sc.ambient = r.number_in(root, "ambient", "", 0.1, 0, 1e6);

    // Lights.
    if (root.contains("lights")) {
        const json& L = root["lights"];
        if (!L.is_array()) r.fail("lights", "expected an array");
        if (L.size() > lim.max_lights)
            r.fail("lights", "more than " + std::to_string(lim.max_lights) + " lights");
        for (size_t k = 0; k < L.size(); ++k) {
            const std::string f = "lights[" + std::to_string(k) + "]";
            if (!L[k].is_object()) r.fail(f, "expected an object");
            if (!L[k].contains("position")) r.fail(f + ".position", "missing");
            Light l;
            l.position = r.point(L[k]["position"], f + ".position");
            if (L[k].contains("color")) l.color = r.colour(L[k]["color"], f + ".color");
            sc.lights.push_back(l);
        }
    }

    // Materials.
    std::map<std::string, int> material_index;
    if (root.contains("materials")) {
        const json& M = root["materials"];
        if (!M.is_object()) r.fail("materials", "expected an object of named materials");
        for (auto it = M.begin(); it != M.end(); ++it) {
            const std::string f = "materials." + it.key();
            if (!it->is_object()) r.fail(f, "expected an object");
            Material m;
            m.name = it.key();
            if (it->contains("color")) m.color = r.colour((*it)["color"], f + ".color");
            m.diffuse = r.number_in(*it, "diffuse", f, m.diffuse, 0, 1e6);
            m.specular = r.number_in(*it, "specular", f, m.specular, 0, 1e6);
            m.shininess = r.number_in(*it, "shininess", f, m.shininess, 0, 1e4);
            m.reflect = r.number_in(*it, "reflect", f, m.reflect, 0, 1);
            m.transmit = r.number_in(*it, "transmit", f, m.transmit, 0, 1);
            m.ior = r.number_in(*it, "ior", f, m.ior, 1e-3, 100);
            material_index[m.name] = static_cast<int>(sc.materials.size());
            sc.materials.push_back(m);
        }
    }
    if (sc.materials.empty()) { // an implicit default material
        sc.materials.push_back(Material{"default"});
        material_index["default"] = 0;
    }

    // Objects.
    auto O = root.find("objects");
    if (O == root.end()) r.fail("objects", "missing");
    if (!O->is_array() || O->empty()) r.fail("objects", "expected a non-empty array");
    if (O->size() > lim.max_objects)
        r.fail("objects", std::to_string(O->size()) + " objects exceed the limit of " +
                              std::to_string(lim.max_objects));
    // Each model file is read once, however many objects name it (by its
    // canonical path, so "a.json" and "./a.json" are one file).
    std::map<std::filesystem::path, Model> models;
    long long total_points = 0;
    for (size_t k = 0; k < O->size(); ++k) {
        const std::string f = "objects[" + std::to_string(k) + "]";
        const json& o = (*O)[k];
        if (!o.is_object()) r.fail(f, "expected an object");
        auto mp = o.find("model");
        if (mp == o.end()) r.fail(f + ".model", "missing");
        if (!mp->is_string()) r.fail(f + ".model", "expected a file name");
        SceneObject so;
        so.model_path = (folder / mp->get<std::string>()).string();
        if (o.contains("material")) {
            if (!o["material"].is_string()) r.fail(f + ".material", "expected a material name");
            auto mi = material_index.find(o["material"].get<std::string>());
            if (mi == material_index.end())
                r.fail(f + ".material",
                       "no material named '" + o["material"].get<std::string>() + "'");
            so.material = mi->second;
        }
        double T[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
        if (o.contains("transform")) {
            const json& t = o["transform"];
            if (!t.is_array() || t.size() != 16)
                r.fail(f + ".transform", "expected 16 numbers (4x4, row-major)");
            for (int i = 0; i < 16; ++i)
                T[i] = r.number(t[i], f + ".transform[" + std::to_string(i) + "]");
            if (T[12] != 0 || T[13] != 0 || T[14] != 0 || T[15] != 1)
                r.fail(f + ".transform", "the last row must be 0 0 0 1 (affine transforms only)");
        }
        std::error_code ec;
        std::filesystem::path key = std::filesystem::weakly_canonical(so.model_path, ec);
        if (ec) key = so.model_path;
        auto cached = models.find(key);
        if (cached == models.end()) {
            cached =
                models.emplace(key, load_model(so.model_path)).first; // errors name the model file
            sc.model_files.push_back(so.model_path);
            const Model& loaded = cached->second;
            sc.model.warnings.insert(sc.model.warnings.end(), loaded.warnings.begin(),
                                     loaded.warnings.end());
        }
        const Model& m = cached->second;
        // The limits hold for the whole scene, every object's copy counted.
        if (sc.model.surfaces.size() + m.surfaces.size() > lim.max_surfaces)
            r.fail(f, "the scene's objects hold more than " + std::to_string(lim.max_surfaces) +
                          " surfaces in all");
        for (const BSplineSurface& s : m.surfaces)
            total_points += static_cast<long long>(s.points.size());
        if (total_points > lim.max_control_points)
            r.fail(f, "the scene's objects hold more than " +
                          std::to_string(lim.max_control_points) + " control points in all");
        so.first_surface = static_cast<int>(sc.model.surfaces.size());
        so.surface_count = static_cast<int>(m.surfaces.size());
        Box3 box;
        for (const BSplineSurface& model_surface : m.surfaces) {
            BSplineSurface s = model_surface;
            for (Vec3& p : s.points) {
                p = {T[0] * p.x + T[1] * p.y + T[2] * p.z + T[3],
                     T[4] * p.x + T[5] * p.y + T[6] * p.z + T[7],
                     T[8] * p.x + T[9] * p.y + T[10] * p.z + T[11]};
                for (int i = 0; i < 3; ++i)
                    if (!(std::abs(p[i]) <= lim.max_coordinate)) {
                        std::ostringstream os;
                        os << "puts a control point of " << so.model_path
                           << " beyond the scene coordinate limit of " << lim.max_coordinate
                           << " (docs/formats.md, Limits)";
                        r.fail(o.contains("transform") ? f + ".transform" : f, os.str());
                    }
                box.extend(p);
            }
            sc.model.surfaces.push_back(std::move(s));
            sc.surface_material.push_back(so.material);
        }
        // A model collapsed to one point (all its control points equal, or a
        // zero transform) has nothing to render and no scale to work at.
        if (!(box.max_extent() > 0))
            r.fail(o.contains("transform") ? f + ".transform" : f,
                   "maps every control point of " + so.model_path +
                       " to one point (zero extent): nothing to render");
        sc.objects.push_back(so);
    }
    const double extent = control_box(sc.model).max_extent();
    if (!(extent >= lim.min_extent)) {
        std::ostringstream os;
        os << "the objects span " << extent << ", less than the scene limit of " << lim.min_extent
           << " (docs/formats.md, Limits)";
        r.fail("objects", os.str());
    }
    sc.model.source = sc.source;
    return sc;
}

} // namespace seamless
