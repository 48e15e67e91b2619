// SPDX-License-Identifier: MIT
// The seamless program on the CAD files that crash OpenCASCADE
// (../shared/reproducers and the fuzzer's since, step_iges_reproducers.h): info, tessellate,
// convert and a scene naming one end with exit status 2, one line naming the file, and no output
// file; the program itself does not link OpenCASCADE.
#include "model/step_iges_reproducers.h"
#include "test_util.h"

#include <seamless/model/step_iges.h>

#include <catch2/catch.hpp>

#include <algorithm>

using namespace seamless;

namespace {

int lines(const std::string& s) {
    return static_cast<int>(std::count(s.begin(), s.end(), '\n'));
}

} // namespace

TEST_CASE("Every reproducer: info, tessellate, convert and render end with exit 2 and one line",
          "[cli][cad][heavy]") {
    const auto dir = test::scratch_dir("cli-reproducers");
    int n = 0;
    for (const auto& f : test::step_iges_reproducers()) {
        ++n;
        const auto scene = dir / "scene.json";
        test::write_file(scene,
                         R"({"version": 1, "camera": {"eye": [0, -5, 1], "look_at": [0, 0, 0]},
            "objects": [{"model": )" +
                             test::quoted(f) + "}]}");
        const auto out = dir / "out";
        for (const std::string& cmd :
             {"info " + test::quoted(f),
              "tessellate " + test::quoted(f) + " -o " + test::quoted(out.string() + ".glb"),
              "convert " + test::quoted(f) + " -o " + test::quoted(out.string() + ".json"),
              "render " + test::quoted(scene) + " -o " + test::quoted(out.string() + ".png")}) {
            INFO(cmd);
            const auto r = test::run_cli(cmd);
            CHECK(r.status == 2);
            CHECK(lines(r.err) == 1);
            CHECK_THAT(r.err, Catch::StartsWith("error: ") && Catch::Contains(f.string()) &&
                                  Catch::Contains("OpenCASCADE crashed reading it (signal"));
        }
        for (const char* ext : {".glb", ".json", ".png"})
            CHECK_FALSE(std::filesystem::exists(out.string() + ext));
    }
    CHECK(n >= 7);
}

TEST_CASE("Neither the program nor the library links OpenCASCADE", "[cli][cad][heavy]") {
    // ldd lists every library the dynamic loader maps at start-up.
    std::FILE* p = popen(("ldd " + test::quoted(SEAMLESS_CLI)).c_str(), "r");
    REQUIRE(p);
    std::string out;
    char buf[4096];
    while (size_t k = std::fread(buf, 1, sizeof buf, p)) out.append(buf, k);
    CHECK(pclose(p) == 0);
    CHECK_THAT(out, Catch::Contains("libseamless") && !Catch::Contains("libTK"));
}
