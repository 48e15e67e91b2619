// SPDX-License-Identifier: MIT
// Regressions of issue 12 in the scene reader: an all-zero transform (5),
// coordinates the renderer cannot work with (8), 100,000 objects each
// reading the same model again (11), and messages (15).
#include "test_util.h"

#include <seamless/base/error.h>
#include <seamless/render/scene/scene.h>

#include <catch2/catch.hpp>

using namespace seamless;

namespace {

const char* kModel = R"({"version":1,"surfaces":[{"degree":[1,1],"size":[2,2],
  "knots_u":[0,0,1,1],"knots_v":[0,0,1,1],"control_points":[[0,0,0],[0,1,0],[1,0,0],[1,1,1]]}]})";

std::string scene_with(const std::string& objects, const std::string& more = "") {
    return R"({"version": 1, "camera": {"eye": [0, -5, 1], "look_at": [0, 0, 0]}, )" + more +
           R"("objects": )" + objects + "}";
}

std::string error_of(const std::filesystem::path& scene, const SceneLimits& lim = {}) {
    try {
        load_scene(scene, lim);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST_CASE("An all-zero scene transform is an error naming the object", "[scene][hostile][cli]") {
    const auto dir = test::scratch_dir("zero-transform");
    test::write_file(dir / "m.json", kModel);
    test::write_file(dir / "s.json",
                     scene_with(R"([{"model": "m.json"}, {"model": "m.json", "transform":
                       [0,0,0,0, 0,0,0,0, 0,0,0,0, 0,0,0,1]}])"));
    const auto r = test::run_cli("render \"" + (dir / "s.json").string() + "\" -o \"" +
                                     (dir / "s.png").string() + "\" --size 8x8",
                                 "zero-transform");
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Catch::Contains("s.json: objects[1].transform: maps every control point of"));
    CHECK_FALSE(std::filesystem::exists(dir / "s.png"));
}

TEST_CASE("Scene coordinates beyond the render limit are refused", "[scene][hostile]") {
    const auto dir = test::scratch_dir("scene-coordinate-limit");
    test::write_file(dir / "m.json", kModel);
    test::write_file(dir / "far.json", scene_with(R"([{"model": "m.json", "transform":
                       [1e300,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]}])"));
    CHECK_THAT(error_of(dir / "far.json"),
               Catch::Contains("objects[0].transform: puts a control point of"));
    test::write_file(dir / "eye.json", R"({"version": 1, "camera": {"eye": [0, -1.7e308, 1],
      "look_at": [0, 0, 0]}, "objects": [{"model": "m.json"}]})");
    CHECK_THAT(error_of(dir / "eye.json"), Catch::Contains("camera.eye[1]: coordinate"));
    test::write_file(dir / "tiny.json", scene_with(R"([{"model": "m.json", "transform":
                       [1e-70,0,0,0, 0,1e-70,0,0, 0,0,1e-70,0, 0,0,0,1]}])"));
    CHECK_THAT(error_of(dir / "tiny.json"), Catch::Contains("objects: the objects span 1e-70"));
    test::write_file(dir / "ok.json", scene_with(R"([{"model": "m.json"}])"));
    CHECK(error_of(dir / "ok.json").empty());
}

TEST_CASE("100,000 scene objects naming one model read it once", "[scene][hostile][heavy]") {
    const auto dir = test::scratch_dir("scene-many-objects");
    std::filesystem::create_directories(dir / "sub");
    test::write_file(dir / "m.json", kModel);
    std::string objects = "[";
    const char* spellings[] = {"m.json", "./m.json", "sub/../m.json"};
    for (int k = 0; k < 100000; ++k)
        objects += std::string(k ? "," : "") + R"({"model": ")" + spellings[k % 3] + R"("})";
    objects += "]";
    test::write_file(dir / "s.json", scene_with(objects));
    const Scene s = load_scene(dir / "s.json");
    CHECK(s.objects.size() == 100000);
    CHECK(s.model.surfaces.size() == 100000);
    CHECK(s.model_files.size() == 1);
}

TEST_CASE("The scene limits count every object's copy of its model", "[scene][hostile]") {
    const auto dir = test::scratch_dir("scene-limits");
    test::write_file(dir / "m.json", kModel);
    std::string objects = "[";
    for (int k = 0; k < 11; ++k) objects += std::string(k ? "," : "") + R"({"model": "m.json"})";
    objects += "]";
    test::write_file(dir / "s.json", scene_with(objects));
    SceneLimits lim;
    lim.max_objects = 10;
    CHECK_THAT(error_of(dir / "s.json", lim),
               Catch::Contains("objects: 11 objects exceed the limit of 10"));
    lim = {};
    lim.max_control_points = 40; // 4 per object
    CHECK_THAT(
        error_of(dir / "s.json", lim),
        Catch::Contains("objects[10]: the scene's objects hold more than 40 control points"));
    lim = {};
    lim.max_surfaces = 5;
    CHECK_THAT(error_of(dir / "s.json", lim),
               Catch::Contains("objects[5]: the scene's objects hold more than 5 surfaces"));
}

TEST_CASE("Scene messages: top-level members without a dot, a folder is a folder",
          "[scene][hostile][cli]") {
    const auto dir = test::scratch_dir("scene-messages");
    test::write_file(dir / "m.json", kModel);
    test::write_file(dir / "s.json", scene_with(R"([{"model": "m.json"}])", R"("ambient": -1, )"));
    CHECK_THAT(error_of(dir / "s.json"), Catch::Contains("s.json: ambient: value -1 out of range"));
    std::filesystem::create_directories(dir / "folder.json");
    const auto r = test::run_cli("render \"" + (dir / "folder.json").string() + "\" -o \"" +
                                     (dir / "x.png").string() + "\"",
                                 "scene-messages");
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Catch::Contains("folder.json: is a directory, not a scene file"));
}
