// SPDX-License-Identifier: MIT
#include <seamless/render/scene.h>

#include <seamless/base/error.h>

#include <nlohmann/json.hpp>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

namespace seamless {
namespace {

using json = nlohmann::json;

struct Reader {
    std::string file;

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
        double x = number(*it, f + "." + key);
        if (x < lo || x > hi) {
            std::ostringstream os;
            os << "value " << x << " outside " << lo << ".." << hi;
            fail(f + "." + key, os.str());
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
    Vec3 colour(const json& j, const std::string& f) const {
        Vec3 c = vec3(j, f);
        for (int k = 0; k < 3; ++k)
            if (c[k] < 0) fail(f + "[" + std::to_string(k) + "]", "colour components must be >= 0");
        return c;
    }
};

json parse_file(const std::filesystem::path& path) {
    const std::string file = path.string();
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw InputError(file, "", "cannot open file (" + std::string(std::strerror(errno)) + ")");
    std::stringstream ss;
    ss << in.rdbuf();
    try {
        return json::parse(ss.str());
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
    Reader r{path.string()};
    const json root = parse_file(path);
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
    c.eye = r.vec3((*cam)["eye"], "camera.eye");
    c.look_at = r.vec3((*cam)["look_at"], "camera.look_at");
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
            l.position = r.vec3(L[k]["position"], f + ".position");
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
    if (O->size() > lim.max_objects) r.fail("objects", "too many objects");
    const std::filesystem::path folder = path.parent_path();
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
        Model m = load_model(so.model_path); // errors name the model file
        sc.model.warnings.insert(sc.model.warnings.end(), m.warnings.begin(), m.warnings.end());
        so.first_surface = static_cast<int>(sc.model.surfaces.size());
        so.surface_count = static_cast<int>(m.surfaces.size());
        for (BSplineSurface& s : m.surfaces) {
            for (Vec3& p : s.points)
                p = {T[0] * p.x + T[1] * p.y + T[2] * p.z + T[3],
                     T[4] * p.x + T[5] * p.y + T[6] * p.z + T[7],
                     T[8] * p.x + T[9] * p.y + T[10] * p.z + T[11]};
            sc.model.surfaces.push_back(std::move(s));
            sc.surface_material.push_back(so.material);
        }
        sc.objects.push_back(so);
    }
    sc.model.source = sc.source;
    return sc;
}

} // namespace seamless
