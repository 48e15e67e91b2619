// SPDX-License-Identifier: MIT
// A scene to render: camera, lights, materials and B-spline objects (scene
// format version 1, docs/formats.md). Object transforms are applied to the
// control points when the scene is loaded (affine maps commute with B-spline
// and NURBS evaluation), so the renderer sees world-space surfaces only.
#pragma once

#include <seamless/base/vec.h>
#include <seamless/model/model.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace seamless {

struct Camera {
    Vec3 eye{0, -10, 3}, look_at{0, 0, 0}, up{0, 0, 1};
    double fov_deg = 40; // vertical field of view
    int width = 640, height = 480;
};

struct Light {
    Vec3 position;
    Vec3 color{1, 1, 1}; // RGB intensity; a light with colour 0 is off and costs nothing
    bool on() const { return color.x > 0 || color.y > 0 || color.z > 0; }
};

struct Material {
    std::string name;
    Vec3 color{0.8, 0.8, 0.8};
    double diffuse = 0.7, specular = 0.3, shininess = 20;
    double reflect = 0, transmit = 0, ior = 1.5;
};

struct SceneObject {
    std::string model_path;
    int material = 0; // index into Scene::materials
    // The scene names no material for it and its file has colours (a STEP or
    // IGES file's styles, Model::assembly): its coloured faces are in the
    // file's colours (scene.cpp), the others in `material`.
    bool file_colours = false;
    int first_surface; // this object's surfaces in Scene::model.surfaces
    int surface_count;
};

struct Scene {
    std::string source;
    Camera camera;
    int levels = 16; // representable intensities per channel; level k -> round(255 k / (levels-1))
    Vec3 background{0, 0, 0};
    double ambient = 0.1;
    std::vector<Light> lights;
    std::vector<Material> materials;
    std::vector<SceneObject> objects;
    int max_depth = 2;
    // All objects' surfaces, transformed to world space, in object order.
    Model model;
    // material index of each surface of `model` (a B-rep face's is its
    // surface's: the readers give each face a surface of its own)
    std::vector<int> surface_material;
    // The model files read, each once however many objects name it.
    std::vector<std::string> model_files;
};

// Limits of a scene (docs/formats.md, Limits). Objects share the models they
// name (each file is read once), but each object holds its own transformed
// copy, so the surfaces and control points are counted over all objects.
struct SceneLimits {
    int max_width = 16384, max_height = 16384;
    int max_levels = 65536;
    int max_depth = 16;
    size_t max_objects = 100000, max_lights = 1000;
    size_t max_surfaces = 1'000'000;
    long long max_control_points = 10'000'000;
    std::uintmax_t max_file_bytes = std::uintmax_t(1) << 26; // 64 MiB
    // World coordinates (camera, lights, transformed control points) stay
    // within 2^200 in magnitude, and the objects together span at least
    // 2^-200. The renderer works on world coordinates without rescaling (its
    // interval Newton solves multiply several coordinates, and power-form
    // coefficients of high degree grow): the teapot scene scaled by 2^k
    // renders the same image for |k| <= 250 and breaks at |k| = 280, where
    // products overflow or underflow; 2^200 leaves 2^50 for degree-9 patches.
    // Models alone allow 2^510 (kMaxCoordinate): tessellation works at unit scale.
    double max_coordinate = 0x1p200;
    double min_extent = 0x1p-200;
    // How the objects' model files are read (the STEP/IGES reader's limits:
    // render --reader-time-limit, --reader-memory-limit); an assembly is
    // always placed, whatever keep_assembly says.
    ModelLoadOptions models;
};

// Reads a scene file and the models it names (paths relative to the scene's
// folder). Throws InputError naming the file and the field on any defect.
Scene load_scene(const std::filesystem::path& path, const SceneLimits& limits = {});
// The same from the scene's text; `file` names it in messages and model paths
// are relative to `folder`.
Scene parse_scene(const std::string& text, const std::string& file,
                  const std::filesystem::path& folder, const SceneLimits& limits = {});

} // namespace seamless
