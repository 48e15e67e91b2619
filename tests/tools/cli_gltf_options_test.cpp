// SPDX-License-Identifier: MIT
// seamless tessellate's glTF options: --merge (one mesh and node for every
// instance placed) and --units (metres by default, keep).
#include "test_util.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>

using namespace seamless;

namespace {

// A .glb's JSON chunk (bytes 20 on, its length at 12).
nlohmann::json load(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    const std::string bytes = s.str();
    REQUIRE(bytes.size() > 20);
    std::uint32_t length = 0;
    std::memcpy(&length, bytes.data() + 12, 4);
    return nlohmann::json::parse(bytes.substr(20, length));
}

// The largest |coordinate| of the POSITION accessors' bounds.
double extent(const nlohmann::json& g) {
    double e = 0;
    for (const auto& a : g["accessors"])
        for (const char* bound : {"min", "max"})
            if (a.contains(bound))
                for (double v : a[bound]) e = std::max(e, std::abs(v));
    return e;
}

} // namespace

TEST_CASE("tessellate --merge and --units on a millimetre STEP part", "[cli][gltf][heavy]") {
    CHECK_THAT(test::run_cli("tessellate --help").out,
               Catch::Contains("--merge") && Catch::Contains("--units"));
    const auto dir = test::scratch_dir("cli_gltf_options");
    const std::string model =
        test::quoted(test::model_path("cad/b123d_M6-1x12-countersunk-screw.step"));
    const auto run = [&](const std::string& name, const std::string& flags) {
        const auto r = test::run_cli("tessellate " + model + " --tolerance 0.02 -o " +
                                     test::quoted(dir / name) + " " + flags);
        INFO(r.err);
        CHECK(r.status == 0);
        return r;
    };
    const auto metres = run("m.glb", "");
    CHECK_THAT(metres.out, Catch::Contains("scaled to metres: 1 file unit = 0.001 m"));
    run("keep.glb", "--units keep");
    run("merged.glb", "--merge --units keep");
    const nlohmann::json m = load(dir / "m.glb"), keep = load(dir / "keep.glb"),
                         merged = load(dir / "merged.glb");
    CHECK(extent(m) == Approx(0.001 * extent(keep)).epsilon(1e-6));
    CHECK(extent(keep) > 5); // an M6 screw 12 mm long, in millimetres
    REQUIRE(merged["nodes"].size() == 1);
    REQUIRE(merged["meshes"].size() == 1);
    const auto& prims = merged["meshes"][0]["primitives"];
    REQUIRE(prims.size() == 1); // one colour (none)
    CHECK(prims[0]["extras"]["faces"].size() > 1);
    CHECK(extent(merged) == Approx(extent(keep)).epsilon(1e-6));
    // --merge and --flatten exclude each other; --units takes two words.
    CHECK(test::run_cli("tessellate " + model + " -o x.glb --merge --flatten").status != 0);
    CHECK(test::run_cli("tessellate " + model + " -o x.glb --units inches").status != 0);
}

TEST_CASE("check judges a placed glTF's solids apart, as a PLY's", "[cli][gltf][heavy]") {
    // as1's 18 solids touch where the file places them (bolts in holes): with
    // the solids in the primitives' extras, `check --closed` passes the glb of
    // every instance placed as it passes the PLY; --union judges it whole.
    const auto dir = test::scratch_dir("cli_gltf_solids");
    const std::string model = test::quoted(test::model_path("cad/occt_as1-oc-214-mat.stp"));
    for (const char* flags : {"--merge", "--flatten"}) {
        INFO(flags);
        const auto glb = test::quoted(dir / "as1.glb");
        REQUIRE(test::run_cli("tessellate " + model + " -o " + glb + " " + flags).status == 0);
        const nlohmann::json g = load(dir / "as1.glb");
        CHECK(g["meshes"][0]["primitives"][0]["extras"].contains("solids"));
        const auto apart = test::run_cli("check --closed " + glb);
        INFO(apart.out);
        CHECK(apart.status == 0);
        CHECK_THAT(apart.out, Catch::Contains("judged apart: 18 solids"));
        CHECK(test::run_cli("check --closed --union " + glb).status == 1);
    }
}
