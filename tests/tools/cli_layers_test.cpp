// SPDX-License-Identifier: MIT
// seamless info prints a STEP file's layers (--json: "layers"), tessellate
// --stats counts the triangles of every instance placed beside each part's,
// and the glTF's scene extras name the layers.
#include "test_util.h"

#include <seamless/base/files/input_file.h>
#include <seamless/mesh/io/mesh_io.h>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cstdint>

using namespace seamless;

namespace {

std::string read_text(const std::filesystem::path& p) {
    return read_input_file(p, std::uintmax_t(1) << 30, "test");
}

const std::filesystem::path kAs1 = test::model_path("cad/occt_as1-oc-214-mat.stp");

} // namespace

TEST_CASE("info prints the layers of a STEP assembly, named as in the file",
          "[cli][layers][heavy]") {
    const std::string text = read_text(kAs1);
    const auto j = test::run_cli("info --json " + test::quoted(kAs1));
    REQUIRE(j.status == 0);
    const nlohmann::json info = nlohmann::json::parse(j.out);
    REQUIRE(info.contains("layers"));
    REQUIRE(!info["layers"].empty());
    const size_t parts = info["assembly"]["parts"].size();
    for (const auto& l : info["layers"]) {
        const std::string name = l["name"];
        INFO(name);
        CHECK(text.find("PRESENTATION_LAYER_ASSIGNMENT('" + name + "'") != std::string::npos);
        CHECK(l["visible"] == true);
        CHECK(!l["parts"].empty());
        for (int p : l["parts"]) CHECK(p < static_cast<int>(parts));
    }
    const auto t = test::run_cli("info " + test::quoted(kAs1));
    REQUIRE(t.status == 0);
    const std::string first = info["layers"][0]["name"];
    CHECK_THAT(t.out, Catch::Contains("1 layer:\n  " + first + ": "));
}

TEST_CASE("tessellate --stats counts the placed triangles and each part's instances",
          "[cli][layers][heavy]") {
    const auto dir = test::scratch_dir("cli_layers_stats");
    for (const char* out : {"a.ply", "a.glb"}) {
        INFO(out);
        const auto r =
            test::run_cli("tessellate " + test::quoted(kAs1) + " -o " + test::quoted(dir / out) +
                          " --stats " + test::quoted(dir / "s.json"));
        REQUIRE(r.status == 0);
        const nlohmann::json s = nlohmann::json::parse(read_text(dir / "s.json"));
        long long placed = 0, once = 0;
        REQUIRE(s["parts"].size() > 1);
        for (const auto& p : s["parts"]) {
            CHECK(p["instances"].get<int>() >= 1);
            placed += p["instances"].get<long long>() * p["triangles"].get<long long>();
            once += p["triangles"].get<long long>();
        }
        CHECK(s["placed_triangles"] == placed);
        CHECK(s["triangles"] == once);
        CHECK(s["placed_triangles"] > s["triangles"]); // parts used more than once
        CHECK_THAT(r.out, Catch::Contains(std::to_string(placed) + " triangles"));
        if (std::string(out) == "a.ply") { // the placed mesh, as written
            const TriangleMesh m = read_mesh(dir / out);
            CHECK(m.triangle_count() == s["placed_triangles"].get<long long>());
            CHECK(m.vertex_count() == s["placed_vertices"].get<long long>());
        }
    }
}

TEST_CASE("The glTF of a STEP assembly names its layers in the scene's extras",
          "[cli][layers][heavy]") {
    const auto dir = test::scratch_dir("cli_layers_gltf");
    REQUIRE(
        test::run_cli("tessellate " + test::quoted(kAs1) + " -o " + test::quoted(dir / "a.gltf"))
            .status == 0);
    const nlohmann::json g = nlohmann::json::parse(read_text(dir / "a.gltf"));
    const auto info = nlohmann::json::parse(test::run_cli("info --json " + test::quoted(kAs1)).out);
    const auto& layers = g["scenes"][0]["extras"]["layers"];
    REQUIRE(layers.size() == info["layers"].size());
    for (size_t k = 0; k < layers.size(); ++k) {
        CHECK(layers[k]["name"] == info["layers"][k]["name"]);
        // A part's mesh is the part's index: one mesh per part.
        CHECK(layers[k]["meshes"] == info["layers"][k]["parts"]);
        for (int mesh : layers[k]["meshes"]) CHECK(mesh < static_cast<int>(g["meshes"].size()));
    }
}
