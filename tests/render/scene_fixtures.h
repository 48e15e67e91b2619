// SPDX-License-Identifier: MIT
// Small scenes built in tests: one model under one light, and a bicubic dome.
#pragma once

#include "test_util.h"

#include <seamless/render/scene/scene.h>

#include <nlohmann/json.hpp>

namespace seamless::test {

// A scene of one model seen from `eye` towards `look_at`, written to `dir`.
inline Scene one_model_scene(const std::filesystem::path& dir, const std::string& model_json,
                             Vec3 eye, Vec3 look_at, Vec3 up = {0, 0, 1}) {
    write_file(dir / "model.json", model_json);
    nlohmann::json s = {
        {"version", 1},
        {"camera",
         {{"eye", {eye.x, eye.y, eye.z}},
          {"look_at", {look_at.x, look_at.y, look_at.z}},
          {"up", {up.x, up.y, up.z}},
          {"fov_deg", 40},
          {"width", 64},
          {"height", 48}}},
        {"levels", 16},
        {"background", {0.0, 0.0, 0.0}},
        {"ambient", 0.1},
        {"lights", {{{"position", {eye.x + 1, eye.y + 2, eye.z + 3}}, {"color", {1, 1, 1}}}}},
        {"materials",
         {{"m",
           {{"color", {0.9, 0.6, 0.3}}, {"diffuse", 0.8}, {"specular", 0.4}, {"shininess", 25}}}}},
        {"objects", {{{"model", "model.json"}, {"material", "m"}}}}};
    write_file(dir / "scene.json", s.dump());
    return load_scene(dir / "scene.json");
}

// One bicubic patch: a gentle dome over [-1,1]^2 in the plane z = 0.
inline std::string dome() {
    nlohmann::json pts = nlohmann::json::array();
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            double x = -1 + 2.0 * i / 3, y = -1 + 2.0 * j / 3;
            pts.push_back({x, y, (i == 1 || i == 2) && (j == 1 || j == 2) ? 0.3 : 0.0});
        }
    nlohmann::json m = {{"version", 1},
                        {"surfaces",
                         {{{"name", "dome"},
                           {"degree", {3, 3}},
                           {"size", {4, 4}},
                           {"knots_u", {0, 0, 0, 0, 1, 1, 1, 1}},
                           {"knots_v", {0, 0, 0, 0, 1, 1, 1, 1}},
                           {"control_points", pts}}}}};
    return m.dump();
}

} // namespace seamless::test
