// SPDX-License-Identifier: MIT
// Regressions of issue 12: an output path that is an input overwrote it (12),
// and --stats into a missing folder failed only after the mesh or image had
// been written (13). Outputs are now checked before the work and written
// together after it.
#include "test_util.h"

#include <catch2/catch.hpp>

#include <fstream>
#include <set>
#include <sstream>

namespace fs = std::filesystem;
using namespace seamless;

namespace {

std::string content(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// Nothing but `expected` in `dir` (no staging files left behind either).
bool only_files(const fs::path& dir, std::set<std::string> expected) {
    std::set<std::string> got;
    for (const auto& e : fs::directory_iterator(dir)) got.insert(e.path().filename().string());
    return got == expected;
}

const char* kModel = R"({"version":1,"surfaces":[{"degree":[1,1],"size":[2,2],
  "knots_u":[0,0,1,1],"knots_v":[0,0,1,1],"control_points":[[0,0,0],[0,1,0],[1,0,0],[1,1,1]]}]})";
const char* kScene = R"({"version": 1, "camera": {"eye": [0.5, -3, 2], "look_at": [0.5, 0.5, 0.5],
  "width": 8, "height": 8}, "lights": [{"position": [2, -4, 4]}], "objects": [{"model": "m.json"}]})";

} // namespace

TEST_CASE("An output that is the same file as an input is refused, by inode not by spelling",
          "[cli][hostile]") {
    const auto dir = test::scratch_dir("output-is-input");
    test::write_file(dir / "m.obj", kModel); // a model whose name looks like a mesh
    test::write_file(dir / "s.json", kScene);
    test::write_file(dir / "m.json", kModel);
    fs::create_hard_link(dir / "m.json", dir / "hard.obj");
    fs::create_symlink(dir / "s.json", dir / "link.png");
    struct Case {
        std::string args, file;
    };
    for (const Case& c :
         {Case{"tessellate " + test::quoted(dir / "m.obj") + " -o " + test::quoted(dir / "m.obj"),
               "m.obj"},
          Case{"tessellate " + test::quoted(dir / "m.json") + " -o " +
                   test::quoted(dir / "." / "hard.obj"),
               "m.json"},
          Case{"tessellate " + test::quoted(dir / "m.json") + " -o " + test::quoted(dir / "x.obj") +
                   " --stats " + test::quoted(dir / "m.json"),
               "m.json"},
          Case{"render " + test::quoted(dir / "s.json") + " -o " + test::quoted(dir / "s.json"),
               "s.json"},
          Case{"render " + test::quoted(dir / "s.json") + " -o " + test::quoted(dir / "link.png"),
               "s.json"},
          Case{"render " + test::quoted(dir / "s.json") + " -o " + test::quoted(dir / "x.png") +
                   " --stats " + test::quoted(dir / "m.json"),
               "m.json"}}) {
        INFO(c.args);
        const std::string before = content(dir / c.file);
        const auto r = test::run_cli(c.args, "output-is-input");
        CHECK(r.status == 2);
        CHECK_THAT(r.err, Catch::Contains("is also an input"));
        CHECK(content(dir / c.file) == before);
    }
    CHECK(only_files(dir, {"m.obj", "s.json", "m.json", "hard.obj", "link.png"}));
}

TEST_CASE("A stats file in a missing folder: nothing written, checked before the work",
          "[cli][hostile]") {
    const auto dir = test::scratch_dir("stats-missing-folder");
    test::write_file(dir / "m.json", kModel);
    test::write_file(dir / "s.json", kScene);
    auto r = test::run_cli("tessellate " + test::quoted(dir / "m.json") + " -o " +
                               test::quoted(dir / "m.obj") + " --stats " +
                               test::quoted(dir / "no" / "stats.json"),
                           "stats-missing");
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Catch::Contains("stats.json: cannot write: folder"));
    r = test::run_cli("render " + test::quoted(dir / "s.json") + " -o " +
                          test::quoted(dir / "s.png") + " --stats " +
                          test::quoted(dir / "no" / "stats.json"),
                      "stats-missing");
    CHECK(r.status == 2);
    CHECK(r.out.empty()); // refused before rendering
    r = test::run_cli("tessellate " + test::quoted(dir / "m.json") + " -o " +
                          test::quoted(dir / "no" / "m.obj") + " --stats " +
                          test::quoted(dir / "stats.json"),
                      "stats-missing");
    CHECK(r.status == 2);
    r = test::run_cli("tessellate " + test::quoted(dir / "m.json") + " -o " +
                          test::quoted(dir / "m.obj") + " --stats " + test::quoted(dir / "m.obj"),
                      "stats-missing");
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Catch::Contains("given twice as an output"));
    CHECK(only_files(dir, {"m.json", "s.json"}));
    // And with every output writable, both appear.
    r = test::run_cli("tessellate " + test::quoted(dir / "m.json") + " -o " +
                          test::quoted(dir / "m.obj") + " --stats " +
                          test::quoted(dir / "stats.json"),
                      "stats-missing");
    INFO(r.err);
    CHECK(r.status == 0);
    CHECK(only_files(dir, {"m.json", "s.json", "m.obj", "stats.json"}));
}
