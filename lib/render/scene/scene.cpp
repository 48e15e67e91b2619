// SPDX-License-Identifier: MIT
#include <seamless/render/scene/scene.h>

#include <seamless/base/files/input_file.h>
#include <seamless/model/brep_placement.h>
#include <seamless/model/json_fields.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace seamless {
namespace {

// The scene's fields: JsonFields and the scene's own checks of points and colours.
struct SceneFields : JsonFields {
    double max_coordinate; // SceneLimits::max_coordinate

    SceneFields(const std::string& file, double max) : JsonFields(file), max_coordinate(max) {}

    // A point of the world: coordinates within max_coordinate.
    Vec3 point(const Json& j, const std::string& f) const {
        const Vec3 p = vec3(j, f);
        for (int k = 0; k < 3; ++k)
            if (std::abs(p[k]) > max_coordinate) {
                std::ostringstream os;
                os << "coordinate " << p[k] << " beyond the scene limit of " << max_coordinate
                   << " (docs/formats.md, Limits)";
                fail(element_field(f, k), os.str());
            }
        return p;
    }
    Vec3 colour(const Json& j, const std::string& f) const {
        Vec3 c = vec3(j, f);
        for (int k = 0; k < 3; ++k)
            if (c[k] < 0) fail(element_field(f, k), "colour components must be >= 0");
        return c;
    }
};

Camera read_camera(const SceneFields& r, const Json& root, const SceneLimits& lim) {
    const Json& cam = r.object(r.member(root, "camera", "camera"), "camera");
    const Json& eye = r.member(cam, "eye", "camera.eye");
    const Json& look_at = r.member(cam, "look_at", "camera.look_at");
    Camera c;
    c.eye = r.point(eye, "camera.eye");
    c.look_at = r.point(look_at, "camera.look_at");
    if (const Json* up = JsonFields::find(cam, "up")) c.up = r.vec3(*up, "camera.up");
    c.fov_deg = r.number_or(cam, "camera", "fov_deg", 40, 1e-3, 179);
    c.width = static_cast<int>(r.integer_or(cam, "camera", "width", 640, 1, lim.max_width));
    c.height = static_cast<int>(r.integer_or(cam, "camera", "height", 480, 1, lim.max_height));
    if (norm(c.look_at - c.eye) == 0) r.fail("camera.look_at", "equals the eye point");
    if (norm(cross(c.look_at - c.eye, c.up)) == 0)
        r.fail("camera.up", "parallel to the viewing direction");
    return c;
}

std::vector<Light> read_lights(const SceneFields& r, const Json& root, const SceneLimits& lim) {
    std::vector<Light> lights;
    const Json* L = JsonFields::find(root, "lights");
    if (!L) return lights;
    r.array(*L, "lights");
    if (L->size() > lim.max_lights)
        r.fail("lights", std::to_string(L->size()) + " lights exceed the limit of " +
                             std::to_string(lim.max_lights));
    for (size_t k = 0; k < L->size(); ++k) {
        const std::string f = element_field("lights", k);
        const Json& l = r.object((*L)[k], f);
        Light light;
        light.position = r.point(r.member(l, "position", f + ".position"), f + ".position");
        if (const Json* c = JsonFields::find(l, "color")) light.color = r.colour(*c, f + ".color");
        lights.push_back(light);
    }
    return lights;
}

// The scene's materials by name, each its index in sc.materials; an implicit
// "default" where the scene names none.
std::map<std::string, int> read_materials(const SceneFields& r, const Json& root, Scene& sc) {
    std::map<std::string, int> index;
    if (const Json* M = JsonFields::find(root, "materials")) {
        r.object(*M, "materials", "an object of named materials");
        for (auto it = M->begin(); it != M->end(); ++it) {
            const std::string f = "materials." + it.key();
            r.object(*it, f);
            Material m;
            m.name = it.key();
            if (const Json* c = JsonFields::find(*it, "color"))
                m.color = r.colour(*c, f + ".color");
            m.diffuse = r.number_or(*it, f, "diffuse", m.diffuse, 0, 1e6);
            m.specular = r.number_or(*it, f, "specular", m.specular, 0, 1e6);
            m.shininess = r.number_or(*it, f, "shininess", m.shininess, 0, 1e4);
            m.reflect = r.number_or(*it, f, "reflect", m.reflect, 0, 1);
            m.transmit = r.number_or(*it, f, "transmit", m.transmit, 0, 1);
            m.ior = r.number_or(*it, f, "ior", m.ior, 1e-3, 100);
            index[m.name] = static_cast<int>(sc.materials.size());
            sc.materials.push_back(m);
        }
    }
    if (sc.materials.empty()) {
        sc.materials.push_back(Material{"default"});
        index["default"] = 0;
    }
    return index;
}

// A file colour as a scene material: the default finish in that colour;
// its transparency (1 - alpha) lets light through unbent, as CAD viewers
// show it (no lens: index of refraction 1).
Material colour_material(const Rgba& c, const std::string& name) {
    Material m;
    m.name = name;
    m.color = {c.r, c.g, c.b};
    m.transmit = 1 - c.a;
    m.ior = 1;
    return m;
}

// A model file a scene names, read once, and the scene material of each of
// its surfaces in the file's colours (-1: a face without a colour; empty
// until an object shows them).
struct SceneModel {
    Model model;
    std::vector<int> surface_material;
};

// The objects of a scene: each names a model file, read once however many
// objects name it (by its canonical path, so "a.json" and "./a.json" are one
// file), and its copy transformed into the scene.
class ObjectReader {
  public:
    ObjectReader(const SceneFields& r, const SceneLimits& lim, const std::filesystem::path& folder,
                 const std::map<std::string, int>& materials)
        : r_(r), lim_(lim), folder_(folder), materials_(materials) {}

    void read(const Json& o, const std::string& f, Scene& sc) {
        r_.object(o, f);
        SceneObject so;
        so.model_path =
            (folder_ / r_.string(r_.member(o, "model", f + ".model"), f + ".model", "a file name"))
                .string();
        const Json* mat = JsonFields::find(o, "material");
        if (mat) {
            const std::string name = r_.string(*mat, f + ".material", "a material name");
            auto mi = materials_.find(name);
            if (mi == materials_.end())
                r_.fail(f + ".material", "no material named '" + name + "'");
            so.material = mi->second;
        }
        double T[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
        const Json* t = JsonFields::find(o, "transform");
        if (t) read_transform(*t, f + ".transform", T);
        SceneModel& sm = model(so.model_path, sc);
        const Model& m = sm.model;
        // The limits hold for the whole scene, every object's copy counted.
        if (sc.model.surfaces.size() + m.surfaces.size() > lim_.max_surfaces)
            r_.fail(f, "the scene's objects hold more than " + std::to_string(lim_.max_surfaces) +
                           " surfaces in all");
        for (const BSplineSurface& s : m.surfaces)
            total_points_ += static_cast<long long>(s.points.size());
        if (total_points_ > lim_.max_control_points)
            r_.fail(f, "the scene's objects hold more than " +
                           std::to_string(lim_.max_control_points) + " control points in all");
        so.first_surface = static_cast<int>(sc.model.surfaces.size());
        so.surface_count = static_cast<int>(m.surfaces.size());
        place(m, T, t ? f + ".transform" : f, so, sc);
        if (!mat) show_file_colours(sm, so, sc); // a scene's material wins over the file's
        sc.objects.push_back(so);
    }

  private:
    void read_transform(const Json& t, const std::string& f, double* T) const {
        if (!t.is_array() || t.size() != 16) r_.fail(f, "expected 16 numbers (4x4, row-major)");
        for (int i = 0; i < 16; ++i) T[i] = r_.number(t[i], element_field(f, i));
        if (T[12] != 0 || T[13] != 0 || T[14] != 0 || T[15] != 1)
            r_.fail(f, "the last row must be 0 0 0 1 (affine transforms only)");
    }

    // The model at path, read on its first use (its errors name the model file).
    SceneModel& model(const std::string& path, Scene& sc) {
        std::error_code ec;
        std::filesystem::path key = std::filesystem::weakly_canonical(path, ec);
        if (ec) key = path;
        auto cached = models_.find(key);
        if (cached == models_.end()) {
            ModelLoadOptions placed = lim_.models;
            placed.keep_assembly = false;
            cached = models_.emplace(key, SceneModel{load_model(path, placed), {}}).first;
            sc.model_files.push_back(path);
            const Model& loaded = cached->second.model;
            sc.model.warnings.insert(sc.model.warnings.end(), loaded.warnings.begin(),
                                     loaded.warnings.end());
        }
        return cached->second;
    }

    // Object so's copy of m, transformed by T, into the scene; f names T in messages.
    void place(const Model& m, const double* T, const std::string& f, const SceneObject& so,
               Scene& sc) const {
        Box3 box;
        for (const BSplineSurface& model_surface : m.surfaces) {
            BSplineSurface s = model_surface;
            for (Vec3& p : s.points) {
                p = {T[0] * p.x + T[1] * p.y + T[2] * p.z + T[3],
                     T[4] * p.x + T[5] * p.y + T[6] * p.z + T[7],
                     T[8] * p.x + T[9] * p.y + T[10] * p.z + T[11]};
                for (int i = 0; i < 3; ++i)
                    if (!(std::abs(p[i]) <= lim_.max_coordinate)) {
                        std::ostringstream os;
                        os << "puts a control point of " << so.model_path
                           << " beyond the scene coordinate limit of " << lim_.max_coordinate
                           << " (docs/formats.md, Limits)";
                        r_.fail(f, os.str());
                    }
                box.extend(p);
            }
            sc.model.surfaces.push_back(std::move(s));
            sc.surface_material.push_back(so.material);
        }
        if (!m.brep.empty()) {
            AffineMap map;
            std::copy(T, T + 12, map.m);
            append_brep(sc.model.brep, m.brep, so.first_surface, map);
        }
        // A model collapsed to one point (all its control points equal, or a
        // zero transform) has nothing to render and no scale to work at.
        if (!(box.max_extent() > 0))
            r_.fail(f, "maps every control point of " + so.model_path +
                           " to one point (zero extent): nothing to render");
    }

    // An object that names no material shows its file's colours (face over
    // solid over part, assembly.h): each colour a face has becomes a scene
    // material when an object of the file first shows it, and the surfaces
    // of the coloured faces take it, in every object of the file. Files
    // without colours cost nothing here.
    static void show_file_colours(SceneModel& sm, SceneObject& so, Scene& sc) {
        const Model& m = sm.model;
        if (m.assembly.colours.empty()) return;
        if (sm.surface_material.empty()) {
            sm.surface_material.assign(m.surfaces.size(), -1);
            std::vector<int> material(m.assembly.colours.size(), -1);
            const std::vector<int> colours = face_colours(m);
            for (size_t f = 0; f < colours.size(); ++f) {
                const int c = colours[f];
                if (c < 0) continue;
                if (material[c] < 0) {
                    material[c] = static_cast<int>(sc.materials.size());
                    sc.materials.push_back(
                        colour_material(m.assembly.colours[c],
                                        std::filesystem::path(so.model_path).filename().string() +
                                            " colour " + std::to_string(c)));
                }
                sm.surface_material[m.brep.faces[f].surface] = material[c];
            }
        }
        for (size_t s = 0; s < sm.surface_material.size(); ++s)
            if (sm.surface_material[s] >= 0) {
                sc.surface_material[so.first_surface + s] = sm.surface_material[s];
                so.file_colours = true;
            }
    }

    const SceneFields& r_;
    const SceneLimits& lim_;
    const std::filesystem::path& folder_;
    const std::map<std::string, int>& materials_;
    std::map<std::filesystem::path, SceneModel> models_;
    long long total_points_ = 0;
};

void read_objects(const SceneFields& r, const Json& root, const std::filesystem::path& folder,
                  const SceneLimits& lim, const std::map<std::string, int>& materials, Scene& sc) {
    const Json& O = r.array(r.member(root, "objects", "objects"), "objects");
    if (O.empty()) r.fail("objects", "expected at least one object");
    if (O.size() > lim.max_objects)
        r.fail("objects", std::to_string(O.size()) + " objects exceed the limit of " +
                              std::to_string(lim.max_objects));
    ObjectReader objects(r, lim, folder, materials);
    for (size_t k = 0; k < O.size(); ++k) objects.read(O[k], element_field("objects", k), sc);
    const double extent = control_box(sc.model).max_extent();
    if (!(extent >= lim.min_extent)) {
        std::ostringstream os;
        os << "the objects span " << extent << ", less than the scene limit of " << lim.min_extent
           << " (docs/formats.md, Limits)";
        r.fail("objects", os.str());
    }
}

} // namespace

Scene load_scene(const std::filesystem::path& path, const SceneLimits& lim) {
    const std::string text = read_input_file(path, lim.max_file_bytes, "scene");
    return parse_scene(text, path.string(), path.parent_path(), lim);
}

Scene parse_scene(const std::string& text, const std::string& file,
                  const std::filesystem::path& folder, const SceneLimits& lim) {
    const SceneFields r(file, lim.max_coordinate);
    const Json root = r.parse_object(text);
    r.check_version(root);
    Scene sc;
    sc.source = file;
    sc.camera = read_camera(r, root, lim);
    sc.levels = static_cast<int>(r.integer_or(root, "", "levels", 16, 2, lim.max_levels));
    sc.max_depth = static_cast<int>(r.integer_or(root, "", "max_depth", 2, 0, lim.max_depth));
    if (const Json* b = JsonFields::find(root, "background"))
        sc.background = r.colour(*b, "background");
    sc.ambient = r.number_or(root, "", "ambient", 0.1, 0, 1e6);
    sc.lights = read_lights(r, root, lim);
    const std::map<std::string, int> materials = read_materials(r, root, sc);
    read_objects(r, root, folder, lim, materials, sc);
    sc.model.source = sc.source;
    return sc;
}

} // namespace seamless
