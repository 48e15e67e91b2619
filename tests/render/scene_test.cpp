// SPDX-License-Identifier: MIT
// Scene reader: the default scene loads; bad scenes name file and member.
#include "test_util.h"

#include <seamless/base/error.h>
#include <seamless/render/scene/scene.h>

#include <catch2/catch.hpp>

using namespace seamless;

TEST_CASE("The default scene loads with transformed objects", "[scene]") {
    const Scene s = load_scene(test::data_dir() / "scenes" / "teapot.json");
    CHECK(s.objects.size() == 2);
    CHECK(s.model.surfaces.size() == 33);
    CHECK(s.surface_material.size() == 33);
    CHECK(s.levels == 16);
    CHECK(s.lights.size() == 1);
}

TEST_CASE("Bad scenes name the file and the member", "[scene][errors]") {
    auto dir = test::scratch_dir("scene-errors");
    test::write_file(dir / "m.json", R"({"version":1,"surfaces":[{"degree":[1,1],"size":[2,2],
      "knots_u":[0,0,1,1],"knots_v":[0,0,1,1],"control_points":[[0,0,0],[0,1,0],[1,0,0],[1,1,0]]}]})");
    const std::string good = R"({"version": 1, "camera": {"eye": [0, -5, 1], "look_at": [0, 0, 0]},
      "materials": {"red": {"color": [1, 0, 0]}},
      "objects": [{"model": "m.json", "material": "red"}]})";
    auto err = [&](const std::string& text) {
        test::write_file(dir / "s.json", text);
        try {
            load_scene(dir / "s.json");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    auto with = [&](const std::string& from, const std::string& to) {
        std::string s = good;
        auto at = s.find(from);
        REQUIRE(at != std::string::npos);
        return s.replace(at, from.size(), to);
    };
    CHECK(err(good).empty());
    CHECK_THAT(err("{"), Catch::Contains("s.json: line 1, column 2: JSON syntax error"));
    CHECK_THAT(err(with("\"version\": 1", "\"version\": 3")),
               Catch::Contains("version: unsupported version 3"));
    CHECK_THAT(err(with("\"eye\": [0, -5, 1]", "\"eye\": [0, -5]")),
               Catch::Contains("camera.eye: expected [x, y, z]"));
    CHECK_THAT(err(with("\"look_at\": [0, 0, 0]", "\"look_at\": [0, -5, 1]")),
               Catch::Contains("camera.look_at: equals the eye point"));
    CHECK_THAT(err(with("\"look_at\": [0, 0, 0]}", "\"look_at\": [0, 0, 0], \"width\": 0}")),
               Catch::Contains("camera.width: value 0 out of range 1..16384"));
    CHECK_THAT(err(with("\"look_at\": [0, 0, 0]}", "\"look_at\": [0, 0, 0], \"width\": 1e9}")),
               Catch::Contains("camera.width: value"));
    CHECK_THAT(err(with("\"material\": \"red\"", "\"material\": \"gold\"")),
               Catch::Contains("objects[0].material: no material named 'gold'"));
    CHECK_THAT(err(with("\"m.json\"", "\"missing.json\"")),
               Catch::Contains("missing.json: cannot open file"));
    CHECK_THAT(err(with("\"color\": [1, 0, 0]", "\"color\": [1, -1, 0]")),
               Catch::Contains("materials.red.color[1]: colour components must be >= 0"));
    CHECK_THAT(
        err(with("\"material\": \"red\"",
                 "\"material\": \"red\", \"transform\": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,1,1]")),
        Catch::Contains("objects[0].transform: the last row must be 0 0 0 1"));
    CHECK_THAT(err(with("\"objects\": [{\"model\": \"m.json\", \"material\": \"red\"}]",
                        "\"objects\": []")),
               Catch::Contains("objects: expected at least one object"));
    CHECK_THAT(err(with("\"version\": 1,", "\"version\": 1, \"levels\": 1,")),
               Catch::Contains("levels: value 1 out of range 2..65536"));
    CHECK_THAT(err(with("\"version\": 1,", "\"version\": 1, \"ambient\": 1e999,")),
               Catch::Contains("s.json: ambient: not a finite number (overflows a double)"));
}
