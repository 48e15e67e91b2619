// SPDX-License-Identifier: MIT
// Model readers: the bundled models load; every kind of bad input gives one
// InputError naming the file and the field.
#include "test_util.h"

#include <seamless/base/error.h>
#include <seamless/model/model.h>
#include <seamless/spline/knot_insertion.h>

#include <catch2/catch.hpp>

using namespace seamless;

namespace {

const char* kGood = R"({"version": 1, "surfaces": [{"name": "s", "degree": [2, 1], "size": [3, 2],
  "knots_u": [0, 0, 0, 1, 1, 1], "knots_v": [0, 0, 1, 1],
  "control_points": [[0,0,0],[0,1,0],[1,0,0],[1,1,1],[2,0,0],[2,1,0]]}]})";

// Parses `text` and returns the error message ("" when it parses).
std::string error_of(const std::string& text) {
    try {
        parse_model_json(text, "model.json");
    } catch (const InputError& e) {
        CHECK(e.file() == "model.json");
        return e.what();
    }
    return "";
}

std::string replace(std::string s, const std::string& from, const std::string& to) {
    auto at = s.find(from);
    REQUIRE(at != std::string::npos);
    return s.replace(at, from.size(), to);
}

} // namespace

TEST_CASE("The bundled models load with the expected patch counts", "[model]") {
    struct Case {
        const char* name;
        size_t surfaces, patches;
    };
    for (Case c :
         {Case{"teapot.json", 32, 32}, Case{"teacup.json", 26, 26}, Case{"teaspoon.json", 16, 16},
          Case{"torus.json", 1, 48}, Case{"sphere.json", 6, 6}, Case{"torus_exact.json", 1, 16},
          Case{"repeated_knot.json", 1, 4}, Case{"bilinear.json", 1, 4},
          Case{"quarter_cylinder.json", 1, 1}}) {
        INFO(c.name);
        Model m = load_model(test::model_path(c.name));
        CHECK(m.surfaces.size() == c.surfaces);
        CHECK(bezier_patches(m).size() == c.patches);
    }
}

TEST_CASE("The .bpt teapot equals the JSON teapot", "[model]") {
    Model a = load_model(test::shared_dir() / "models" / "teapot.bpt");
    Model b = load_model(test::model_path("teapot.json"));
    REQUIRE(a.surfaces.size() == 32);
    for (size_t k = 0; k < 32; ++k) CHECK(a.surfaces[k].points == b.surfaces[k].points);
    CHECK(d_max(a) == 6.525);
}

TEST_CASE("JSON models round-trip bit for bit through to_json", "[model]") {
    Model a = load_model(test::model_path("torus_exact.json"));
    Model b = parse_model_json(to_json(a), "again.json");
    REQUIRE(b.surfaces.size() == a.surfaces.size());
    CHECK(b.surfaces[0].points == a.surfaces[0].points);
    CHECK(b.surfaces[0].weights == a.surfaces[0].weights);
    CHECK(b.surfaces[0].knots_u == a.surfaces[0].knots_u);
}

TEST_CASE("Bad JSON models name the file and the field", "[model][errors]") {
    REQUIRE(error_of(kGood).empty());
    const std::string g = kGood;
    struct Case {
        std::string text, expect;
    };
    const std::vector<Case> cases = {
        {"{\"version\": 1, \"surfaces\": [", "model.json: line 1, column 29: JSON syntax error"},
        {"[1, 2]", "model.json: expected a JSON object"},
        {"{\"surfaces\": []}", "model.json: version: missing"},
        {replace(g, "\"version\": 1", "\"version\": 3"),
         "version: unsupported version 3 (this reader knows 1 and 2)"},
        {replace(g, "\"version\": 1", "\"version\": \"1\""),
         "version: expected an integer, got a string"},
        {"{\"version\": 1, \"surfaces\": []}", "surfaces: expected at least one surface"},
        {"{\"version\": 1, \"surfaces\": {}}", "surfaces: expected an array, got an object"},
        {replace(g, "\"degree\": [2, 1],", ""), "surfaces[0].degree: missing"},
        {replace(g, "\"degree\": [2, 1]", "\"degree\": [2]"),
         "surfaces[0].degree: expected [p, q]"},
        {replace(g, "\"degree\": [2, 1]", "\"degree\": [10, 1]"),
         "surfaces[0].degree[0]: value 10 out of range 1..9"},
        {replace(g, "\"degree\": [2, 1]", "\"degree\": [2.5, 1]"),
         "surfaces[0].degree[0]: expected an integer"},
        {replace(g, "\"size\": [3, 2]", "\"size\": [2, 2]"),
         "surfaces[0].size: control net 2 x 2 too small"},
        {replace(g, "\"knots_u\": [0, 0, 0, 1, 1, 1]", "\"knots_u\": [0, 0, 0, 1, 1]"),
         "surfaces[0].knots_u: expected 6 numbers, got 5"},
        {replace(g, "\"knots_u\": [0, 0, 0, 1, 1, 1]", "\"knots_u\": [0, 0, 0.5, 0.2, 1, 1]"),
         "surfaces[0].knots_u[3]: knots decrease (0.2 after 0.5)"},
        {replace(g, "\"knots_v\": [0, 0, 1, 1]", "\"knots_v\": [0, 0, 0, 1]"),
         "surfaces[0].knots_v: knot 0 has multiplicity 3, above degree+1 = 2"},
        {replace(g, "\"knots_v\": [0, 0, 1, 1]", "\"knots_v\": [0, 1, 1, 1]"),
         "surfaces[0].knots_v: knot 1 has multiplicity 3"},
        {replace(g, "\"knots_u\": [0, 0, 0, 1, 1, 1]", "\"knots_u\": [0, 0, 0, 1e999, 1, 1]"),
         "surfaces[0].knots_u[3]: not a finite number"},
        {replace(g, "\"version\": 1", "\"version\": 1, \"big\": [0, -1e999]"),
         "model.json: big[1]: not a finite number"},
        {replace(g, "[1,1,1]", "[1,1e999,1]"),
         "surfaces[0].control_points[3][1]: not a finite number"},
        {replace(g, "[1,1,1]", "[1,1]"), "surfaces[0].control_points[3]: expected [x, y, z]"},
        {replace(g, "[1,1,1]", "[1,\"a\",1]"),
         "surfaces[0].control_points[3][1]: expected a number, got a string"},
        {replace(g, ",[2,1,0]]", "]"), "surfaces[0].control_points: expected 6 points, got 5"},
        {replace(g, "[2,1,0]]", "[2,1,0]], \"weights\": [1, 1, 0, 1, 1, 1]"),
         "surfaces[0].weights[2]: weight 0 is not a positive finite number"},
        {replace(g, "[2,1,0]]", "[2,1,0]], \"weights\": [1, 1, -2, 1, 1, 1]"),
         "surfaces[0].weights[2]: weight -2 is not"},
        {replace(g, "[2,1,0]]", "[2,1,0]], \"weights\": [1, 1, 1]"),
         "surfaces[0].weights: expected 6 numbers, got 3"},
        {replace(g, "\"size\": [3, 2]", "\"size\": [3000000000, 2000000000]"),
         "surfaces[0].size[0]: value 3000000000 out of range 1..50000000"},
        {replace(g, "\"size\": [3, 2]", "\"size\": [40000, 40000]"),
         "surfaces[0].size: 40000 x 40000 control points exceed the limit"},
        {replace(g, "\"size\": [3, 2]", "\"size\": [-3, 2]"),
         "surfaces[0].size[0]: value -3 out of range"},
        {replace(g, "\"name\": \"s\"", "\"name\": 5"),
         "surfaces[0].name: expected a string, got a number"},
        {replace(g, "\"knots_u\": [0, 0, 0, 1, 1, 1]", "\"knots_u\": [0, 0, 1, 1, 1, 1]"),
         "surfaces[0].knots_u: knot 1 has multiplicity 4"},
        {replace(g, "\"knots_v\": [0, 0, 1, 1]", "\"knots_v\": [0, 1, 1, 2]"),
         "surfaces[0].knots_v: empty domain [1, 1]"},
    };
    for (const Case& c : cases) {
        INFO(c.text);
        std::string err = error_of(c.text);
        CHECK_THAT(err, Catch::Contains(c.expect));
        CHECK(err.find('\n') == std::string::npos); // one line
    }
}

TEST_CASE("Bad .bpt files name the file and the line", "[model][errors]") {
    auto err = [](const std::string& text) {
        try {
            parse_bpt(text, "m.bpt");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    std::string one = "1\n1 1\n0 0 0\n0 1 0\n1 0 0\n1 1 1\n";
    CHECK(err(one).empty());
    CHECK_THAT(err(""), Catch::Contains("m.bpt: line 1: empty file"));
    CHECK_THAT(err("2\n1 1\n0 0 0\n0 1 0\n1 0 0\n1 1 1\n"),
               Catch::Contains("exceeds what the file holds"));
    CHECK_THAT(err("1000000000000\n"),
               Catch::Contains("patch count must be an integer in 1..1000000"));
    CHECK_THAT(err("1\n1 1\n0 0 0\n0 1 0\n1 0 0\n1 1\n"),
               Catch::Contains("unexpected end of file"));
    CHECK_THAT(err("1\n1 1\n0 0 0\n0 x 0\n1 0 0\n1 1 1\n"),
               Catch::Contains("m.bpt: line 4: expected patch 0 point 1 y, got 'x'"));
    CHECK_THAT(err("1\n1 1\n0 0 0\n0 1e999 0\n1 0 0\n1 1 1\n"),
               Catch::Contains("line 4: patch 0 point 1 y is not a finite number"));
    CHECK_THAT(err("1\n12 1\n0 0 0\n0 1 0\n1 0 0\n1 1 1\n"),
               Catch::Contains("degree u must be an integer in 1..9"));
    CHECK_THAT(err(one + "7\n"), Catch::Contains("line 7: unexpected '7' after the last patch"));
}

TEST_CASE("Unreadable files are reported as such", "[model][errors]") {
    CHECK_THROWS_WITH(load_model("/nonexistent/dir/m.json"),
                      Catch::Contains("/nonexistent/dir/m.json: cannot open file"));
    CHECK_THROWS_WITH(load_model(test::data_dir()), Catch::Contains("is a directory"));
}
