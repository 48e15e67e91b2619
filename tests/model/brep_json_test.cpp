// SPDX-License-Identifier: MIT
// The JSON model format, version 2 (a B-rep): written, read back bit for
// bit; every defect of a file refused with the field named; version 1
// unchanged.
#include "brep_test_models.h"
#include "test_util.h"

#include <seamless/base/error.h>
#include <seamless/model/model.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <fstream>
#include <sstream>

using namespace seamless;

namespace {

bool same(const std::vector<double>& a, const std::vector<double>& b) {
    if (a.size() != b.size()) return false;
    for (size_t k = 0; k < a.size(); ++k)
        if (!test::same_bytes(a[k], b[k])) return false;
    return true;
}

bool same(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
    if (a.size() != b.size()) return false;
    for (size_t k = 0; k < a.size(); ++k)
        if (!test::same_bytes(a[k], b[k])) return false;
    return true;
}

bool same(const BSplineCurve& a, const BSplineCurve& b) {
    return a.degree == b.degree && same(a.knots, b.knots) && same(a.points, b.points) &&
           same(a.weights, b.weights);
}

// Every field of two B-reps, doubles bit for bit.
void check_same(const BRep& a, const BRep& b) {
    REQUIRE(a.vertices.size() == b.vertices.size());
    for (size_t k = 0; k < a.vertices.size(); ++k) {
        CHECK(test::same_bytes(a.vertices[k].point, b.vertices[k].point));
        CHECK(test::same_bytes(a.vertices[k].tolerance, b.vertices[k].tolerance));
    }
    REQUIRE(a.curves.size() == b.curves.size());
    for (size_t k = 0; k < a.curves.size(); ++k) CHECK(same(a.curves[k], b.curves[k]));
    REQUIRE(a.pcurves.size() == b.pcurves.size());
    for (size_t k = 0; k < a.pcurves.size(); ++k) CHECK(same(a.pcurves[k], b.pcurves[k]));
    REQUIRE(a.edges.size() == b.edges.size());
    for (size_t k = 0; k < a.edges.size(); ++k) {
        const BRepEdge &x = a.edges[k], &y = b.edges[k];
        CHECK((x.curve == y.curve && x.start == y.start && x.end == y.end));
        CHECK(same({x.t0, x.t1, x.tolerance}, {y.t0, y.t1, y.tolerance}));
    }
    REQUIRE(a.faces.size() == b.faces.size());
    for (size_t k = 0; k < a.faces.size(); ++k) {
        const BRepFace &x = a.faces[k], &y = b.faces[k];
        CHECK((x.surface == y.surface && x.reversed == y.reversed && x.name == y.name));
        REQUIRE(x.loops.size() == y.loops.size());
        for (size_t l = 0; l < x.loops.size(); ++l) {
            REQUIRE(x.loops[l].coedges.size() == y.loops[l].coedges.size());
            for (size_t c = 0; c < x.loops[l].coedges.size(); ++c) {
                const BRepCoedge &p = x.loops[l].coedges[c], &q = y.loops[l].coedges[c];
                CHECK((p.edge == q.edge && p.reversed == q.reversed && p.pcurve == q.pcurve));
            }
        }
    }
    REQUIRE(a.shells.size() == b.shells.size());
    for (size_t k = 0; k < a.shells.size(); ++k)
        CHECK((a.shells[k].faces == b.shells[k].faces && a.shells[k].closed == b.shells[k].closed));
    REQUIRE(a.solids.size() == b.solids.size());
    for (size_t k = 0; k < a.solids.size(); ++k)
        CHECK((a.solids[k].shells == b.solids[k].shells && a.solids[k].name == b.solids[k].name));
}

// The plate with numbers that a careless writer loses: -0, a subnormal, 0.1,
// 1/3 and a rational curve; names that need escaping; a solid.
Model awkward_plate() {
    Model m = test::plate_with_hole();
    BRep& b = m.brep;
    b.vertices[0].point.z = -0.0;
    b.curves[0].points[0].z = -0.0;
    b.vertices[1].tolerance = 5e-324;
    b.edges[2].tolerance = 0.1;
    b.curves[1].weights = {1.0 / 3, 1.0 / 3};
    b.faces[0].name = "plate \"A\"\t\\ \xc3\xa9";
    b.faces[0].reversed = true;
    b.shells[0].closed = true;
    b.solids.push_back({{0}, "solid #7"});
    return m;
}

std::string error_of(const std::string& text, const ModelLimits& limits = {}) {
    try {
        parse_model_json(text, "m.json", limits);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

std::string replace(std::string s, const std::string& from, const std::string& to) {
    const auto at = s.find(from);
    REQUIRE(at != std::string::npos);
    return s.replace(at, from.size(), to);
}

} // namespace

TEST_CASE("Version-2 models round-trip bit for bit: write, read, write gives the same text",
          "[model][brep]") {
    for (const Model& m :
         {awkward_plate(), test::plate_with_hole(), test::revolved(1), test::revolved(0)}) {
        INFO(m.brep.faces[0].name);
        const std::string text = to_json(m);
        CHECK(text.rfind("{\"version\": 2,", 0) == 0);
        const Model back = parse_model_json(text, "back.json");
        CHECK(to_json(back) == text);
        check_same(m.brep, back.brep);
        REQUIRE(back.surfaces.size() == m.surfaces.size());
        CHECK(same(back.surfaces[0].points, m.surfaces[0].points));
    }
}

TEST_CASE("A model without a B-rep is written as version 1, as before", "[model][brep]") {
    Model m = test::plate_with_hole();
    m.brep = {};
    // The version-1 layout, byte for byte, as it was before version 2.
    CHECK(to_json(m) == "{\"version\": 1,\n \"surfaces\": [\n"
                        "  {\"name\": \"plate\", \"degree\": [1, 1], \"size\": [2, 2],\n"
                        "   \"knots_u\": [0, 0, 1, 1],\n   \"knots_v\": [0, 0, 1, 1],\n"
                        "   \"control_points\": [[0, 0, 0], [0, 10, 0], [10, 0, 0], [10, 10, 0]]}\n"
                        " ]}\n");
    CHECK(parse_model_json(to_json(m), "v1.json").brep.empty());
}

TEST_CASE("Version-2 JSON defects are refused with the field named", "[model][brep]") {
    const std::string g = to_json(test::plate_with_hole());
    const std::string r = to_json(test::revolved(0));
    struct Case {
        std::string text, expect;
    };
    const std::string brep_start = "\"brep\": {";
    const std::vector<Case> cases = {
        {replace(g, "\"version\": 2", "\"version\": 3"),
         "m.json: version: unsupported version 3 (this reader knows 1 and 2)"},
        {replace(g, "\"version\": 2", "\"version\": 1"), "m.json: brep: a B-rep needs"},
        {g.substr(0, g.find(",\n \"brep\"")) + "}", "m.json: brep: missing"},
        {replace(g, "\"brep\": {", "\"brep\": [], \"x\": {"),
         "brep: expected an object, got an array"},
        {replace(g, "\"vertices\": [", "\"vertexes\": ["), "brep.vertices: missing"},
        {replace(g, "\"point\": [0, 0, 0]", "\"point\": [0, 0]"),
         "brep.vertices[0].point: expected [x, y, z]"},
        {replace(g, "\"point\": [0, 0, 0]", "\"point\": [0, 1e999, 0]"),
         "brep.vertices[0].point[1]: not a finite number (overflows a double)"},
        {replace(g, "\"tolerance\": 9.9999999999999995e-08}", "\"tolerance\": -1}"),
         "brep.vertices[0].tolerance: tolerance -1 is not a number in 0.."},
        {replace(g, "\"degree\": 1, \"knots\"", "\"degree\": 0, \"knots\""),
         "brep.curves[0].degree: value 0 out of range 1..9"},
        {replace(g, "\"knots\": [0, 0, 1, 1]", "\"knots\": [0, 0, 1]"),
         "brep.curves[0].knots: expected 4 numbers, got 3"},
        {replace(g, "\"knots\": [0, 0, 1, 1]", "\"knots\": [0, 0, 1, 0.5]"),
         "brep.curves[0].knots[3]: knots decrease (0.5 after 1)"},
        {replace(g, "\"points\": [[0, 0], [1, 0]]", "\"points\": [[0, 0, 0], [1, 0]]"),
         "brep.pcurves[0].points[0]: expected [u, v]"},
        {replace(g, "\"points\": [[0, 0, 0], [10, 0, 0]]}",
                 "\"points\": [[0, 0, 0], [10, 0, 0]], \"weights\": [1]}"),
         "brep.curves[0].weights: expected 2 numbers, got 1"},
        {replace(g, "\"points\": [[0, 0, 0], [10, 0, 0]]}",
                 "\"points\": [[0, 0, 0], [10, 0, 0]], \"weights\": [1, 0]}"),
         "brep.curves[0].weights[1]: weight 0 is not a positive finite number"},
        {replace(g, "{\"curve\": 0,", "{\"curve\": \"0\","),
         "brep.edges[0].curve: expected an integer, got a string"},
        {replace(g, "{\"curve\": 0,", "{\"curve\": -1,"),
         "brep.edges[0].curve: value -1 out of range 0..9999999"},
        {replace(g, "{\"curve\": 0,", "{\"curve\": 1e300,"),
         "brep.edges[0].curve: value 1e+300 out of range 0..9999999"},
        {replace(g, "{\"curve\": 0,", "{\"curve\": 8,"),
         "brep.edges[0].curve: index 8 out of range 0..7 (curves)"},
        {replace(g, "\"range\": [0, 1], \"vertices\": [0, 1]",
                 "\"range\": [0, 1, 2], \"vertices\": [0, 1]"),
         "brep.edges[0].range: expected [t0, t1]"},
        {replace(g, "\"range\": [0, 1], \"vertices\": [0, 1]",
                 "\"range\": [1, 0], \"vertices\": [0, 1]"),
         "brep.edges[0].range: [1, 0]: t0 must be below t1"},
        {replace(g, "\"vertices\": [0, 1]", "\"vertices\": [0]"),
         "brep.edges[0].vertices: expected [start, end]"},
        {replace(r, "{\"curve\": null, \"range\": [0, 1], \"vertices\": [1, 1]",
                 "{\"curve\": null, \"range\": [0, 1], \"vertices\": [1, 0]"),
         "brep.edges[1].vertices: a degenerate edge (no curve) starts and ends at one vertex"},
        {replace(g, "\"surface\": 0,", "\"surface\": 1,"),
         "brep.faces[0].surface: index 1 out of range 0..0 (surfaces)"},
        {replace(g, "\"reversed\": false, \"name\"", "\"reversed\": 0, \"name\""),
         "brep.faces[0].reversed: expected true or false, got a number"},
        {replace(g, "\"name\": \"plate\", \"loops\"", "\"name\": 7, \"loops\""),
         "brep.faces[0].name: expected a string, got a number"},
        {replace(g, "{\"coedges\": [{\"edge\": 7", "{\"edges\": [{\"edge\": 7"),
         "brep.faces[0].loops[1].coedges: missing"},
        {replace(g, "{\"edge\": 1, \"reversed\": false, \"pcurve\": 1}",
                 "{\"edge\": 1, \"reversed\": false}"),
         "brep.faces[0].loops[0].coedges[1].pcurve: missing"},
        {replace(g, "{\"edge\": 2, \"reversed\": false, \"pcurve\": 2}",
                 "{\"edge\": 2, \"reversed\": false, \"pcurve\": 3}"),
         "brep.faces[0].loops[0].coedges[2].pcurve: starts at (0, 1)"},
        {replace(g, "{\"edge\": 2, \"reversed\": false", "{\"edge\": 4, \"reversed\": false"),
         "brep.faces[0].loops[0].coedges[2]: starts at vertex 4 but coedges[1] ends at vertex 2"},
        {replace(g, "\"faces\": [0], \"closed\"", "\"faces\": [0, 1], \"closed\""),
         "brep.shells[0].faces[1]: index 1 out of range 0..0 (faces)"},
        {replace(g, "\"solids\": []", "\"solids\": [{\"shells\": [2]}]"),
         "brep.solids[0].shells[0]: index 2 out of range 0..0 (shells)"},
        {replace(g, "\"solids\": []", "\"solids\": {}"),
         "brep.solids: expected an array, got an object"},
    };
    for (const Case& c : cases) {
        INFO(c.expect);
        CHECK_THAT(error_of(c.text), Catch::Contains(c.expect));
    }
    // A face is what version 2 adds.
    std::string empty = g.substr(0, g.find("\"brep\"")) +
                        "\"brep\": {\"vertices\": [], \"curves\": [], \"pcurves\": [], "
                        "\"edges\": [], \"faces\": []}}";
    CHECK(error_of(empty) == "m.json: brep.faces: expected at least one face");
}

TEST_CASE("Hostile version-2 sizes are refused before anything is allocated for them",
          "[model][brep][hostile]") {
    const std::string g = to_json(test::plate_with_hole());
    ModelLimits limits;
    limits.max_brep_items = 7;
    CHECK(error_of(g, limits) == "m.json: brep.vertices: 8 vertices exceed the limit of 7");
    limits.max_brep_items = 4; // the cone: 2 vertices, 3 curves and edges, 4 pcurves, 4 coedges
    const std::string r = to_json(test::revolved(0));
    CHECK(error_of(r, limits).empty());
    CHECK(error_of(replace(r, "{\"coedges\": [", "{\"coedges\": [{\"edge\": 0, \"pcurve\": 0},"),
                   limits) ==
          "m.json: brep.faces[0].loops[0].coedges: 5 coedges exceed the limit of 4");
    limits = {};
    limits.max_curve_points = 8;
    CHECK(error_of(r, limits) ==
          "m.json: brep.curves[0].points: 9 control points exceed the limit of 8");
    // An index near 2^63 and one past the limit, neither wrapping.
    CHECK_THAT(error_of(replace(g, "{\"edge\": 1,", "{\"edge\": 9223372036854775807,")),
               Catch::Contains("coedges[1].edge: value 9223372036854775807 out of range"));
    CHECK_THAT(error_of(replace(g, "{\"edge\": 1,", "{\"edge\": 18446744073709551615,")),
               Catch::Contains("coedges[1].edge: value 18446744073709551615 out of range"));
}

TEST_CASE("The CLI refuses a bad version-2 model with exit status 2 and one line",
          "[model][brep][cli]") {
    const auto dir = test::scratch_dir("brep-json-cli");
    std::string g = to_json(test::plate_with_hole());
    g = replace(g, "{\"edge\": 5, \"reversed\": true", "{\"edge\": 5, \"reversed\": false");
    test::write_file(dir / "bad.json", g);
    const auto r = test::run_cli("info \"" + (dir / "bad.json").string() + "\"", "brep-json");
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Catch::Contains("bad.json: brep.faces[0].loops[1].coedges[2]: starts at "
                                      "vertex 5 but coedges[1] ends at vertex 6"));
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
}

TEST_CASE("The version-2 example of docs/formats.md reads and validates", "[model][brep]") {
    std::ifstream in(test::data_dir() / ".." / "docs" / "formats.md");
    std::stringstream doc;
    doc << in.rdbuf();
    const std::string text = doc.str();
    const auto at = text.find("```json\n", text.find("## Model: JSON, version 2 (B-rep)"));
    REQUIRE(at != std::string::npos);
    const auto start = at + 8, end = text.find("```", start);
    const Model m = parse_model_json(text.substr(start, end - start), "formats.md");
    REQUIRE(m.brep.faces.size() == 1);
    CHECK(m.brep.faces[0].loops.size() == 2);
    CHECK(m.brep.edges.size() == 8);
    CHECK(m.brep.faces[0].loops[1].coedges[0].reversed);
}
