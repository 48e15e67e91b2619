// SPDX-License-Identifier: MIT
// Regressions of issue 12 in model reading: /dev/zero read until memory ran
// out (4), coordinates near 1.7e308 accepted (8), and messages that echoed
// raw bytes or named no file (15).
#include "test_util.h"

#include <seamless/base/error.h>
#include <seamless/base/files/input_file.h>
#include <seamless/model/model.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <new>
#include <sstream>

using namespace seamless;

TEST_CASE("/dev/zero as a model is refused at once as not a regular file",
          "[model][hostile][cli]") {
    auto r = test::run_cli("info /dev/zero", "dev-zero");
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Catch::Contains("/dev/zero: not a regular file"));
    // So is a scene object naming it.
    const auto dir = test::scratch_dir("dev-zero-scene");
    test::write_file(dir / "s.json", R"({"version": 1, "camera": {"eye": [0, -5, 0], "look_at":
      [0, 0, 0]}, "objects": [{"model": "/dev/zero"}]})");
    r = test::run_cli("render \"" + (dir / "s.json").string() + "\" -o \"" +
                          (dir / "s.png").string() + "\"",
                      "dev-zero");
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Catch::Contains("/dev/zero: not a regular file"));
    CHECK_FALSE(std::filesystem::exists(dir / "s.png"));
}

TEST_CASE("A model file larger than the limit is refused before reading", "[model][hostile]") {
    const auto dir = test::scratch_dir("model-size-limit");
    test::write_file(dir / "m.json", test::bilinear_model("[[0,0,0],[0,1,0],[1,0,0],[1,1,1]]"));
    ModelLimits small;
    small.max_file_bytes = 100;
    try {
        load_model(dir / "m.json", small);
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK_THAT(std::string(e.what()),
                   Catch::Contains("exceeds the model file limit of 100 bytes"));
    }
    CHECK(load_model(dir / "m.json").surfaces.size() == 1);
}

TEST_CASE("Coordinates near 1.7e308 are refused with the documented limit",
          "[model][hostile][cli]") {
    const auto dir = test::scratch_dir("huge-coordinates");
    test::write_file(dir / "huge.json",
                     test::bilinear_model("[[1.7e308,0,0],[0,1,0],[-1.7e308,0,0],[1,1,1]]"));
    auto r = test::run_cli("tessellate \"" + (dir / "huge.json").string() + "\" -o \"" +
                               (dir / "huge.off").string() + "\"",
                           "huge-coordinates");
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Catch::Contains("huge.json: surfaces[0].control_points[0][0]: coordinate "
                                      "1.7e+308 beyond the limit of"));
    CHECK_FALSE(std::filesystem::exists(dir / "huge.off"));
    // The limit is 2^510: just inside reads, just outside does not.
    CHECK(kMaxCoordinate == std::ldexp(1.0, 510));
    auto text = [](double x) {
        std::ostringstream os;
        os.precision(17);
        os << x;
        return os.str();
    };
    const std::string in = text(kMaxCoordinate), out = text(std::nextafter(kMaxCoordinate, 1e308));
    CHECK_NOTHROW(parse_model_json(
        test::bilinear_model("[[" + in + ",0,0],[0,1,0],[1,0,0],[1,1,1]]"), "in.json"));
    CHECK_THROWS_AS(
        parse_model_json(test::bilinear_model("[[" + out + ",0,0],[0,1,0],[1,0,0],[1,1,1]]"),
                         "o.json"),
        InputError);
    CHECK_THROWS_AS(parse_bpt("1\n1 1\n0 0 0\n0 1 0\n1 0 -1e300\n1 1 1\n", "b.bpt"), InputError);
    // Knots and weights have their limits too.
    CHECK_THROWS_AS(
        parse_model_json(R"({"version": 1, "surfaces": [{"degree": [1, 1], "size": [2, 2],
      "knots_u": [-1e300, -1e300, 1e300, 1e300], "knots_v": [0, 0, 1, 1],
      "control_points": [[0,0,0],[0,1,0],[1,0,0],[1,1,1]]}]})",
                         "k.json"),
        InputError);
    CHECK_THROWS_AS(
        parse_model_json(R"({"version": 1, "surfaces": [{"degree": [1, 1], "size": [2, 2],
      "knots_u": [0, 0, 1, 1], "knots_v": [0, 0, 1, 1], "weights": [1, 1, 1, 1e300],
      "control_points": [[0,0,0],[0,1,0],[1,0,0],[1,1,1]]}]})",
                         "w.json"),
        InputError);
}

TEST_CASE("Error lines escape control bytes and terminal escapes from the input",
          "[model][hostile][cli]") {
    const auto dir = test::scratch_dir("escape-error-line");
    test::write_file(dir / "m.bpt", "1\n1 1\n0 0 0\n0 1 0\n1 0 \x1b[31mred\x07\xff\n1 1 1\n");
    const auto r = test::run_cli("info \"" + (dir / "m.bpt").string() + "\"", "escape");
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Catch::Contains("got '\\e[31mred\\x07\\xff'"));
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    for (char c : r.err) CHECK((c == '\n' || static_cast<unsigned char>(c) >= 0x20));
    // Valid UTF-8 stays readable; C1 controls (U+009B is a one-byte CSI) do not.
    CHECK(InputError("f\xc3\xa9.json", "", "x").what() == std::string("f\xc3\xa9.json: x"));
    CHECK(InputError("f\xc2\x9b"
                     "2J.json",
                     "", "x")
              .what() == std::string("f\\xc2\\x9b2J.json: x"));
    CHECK(InputError("a\nb", "", "x").what() == std::string("a\\nb: x"));
}

TEST_CASE("Running out of memory on a file names the file", "[model][hostile]") {
    try {
        naming_file_on_oom("big.json", []() -> int { throw std::bad_alloc(); });
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK(std::string(e.what()) == "big.json: out of memory while reading it");
    }
}

TEST_CASE("A folder given as a model says it is a folder", "[model][hostile]") {
    const auto dir = test::scratch_dir("model-folder");
    std::filesystem::create_directories(dir / "m.json");
    try {
        load_model(dir / "m.json");
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK_THAT(std::string(e.what()),
                   Catch::Contains("m.json: is a directory, not a model file"));
    }
}
