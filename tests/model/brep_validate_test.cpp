// SPDX-License-Identifier: MIT
// validate_brep: the test B-reps pass; each rule, broken alone, is refused
// with the field that breaks it named.
#include "brep_test_models.h"

#include <seamless/base/error.h>
#include <seamless/model/model.h>

#include <catch2/catch.hpp>

#include <functional>
#include <limits>

using namespace seamless;

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

struct Refusal {
    std::string field, message;
};

// The field and message validate_brep names, or two empty strings.
Refusal refusal(const Model& m, const ModelLimits& limits = {}) {
    try {
        validate_brep(m, "m.json", limits);
    } catch (const InputError& e) {
        CHECK(e.file() == "m.json");
        return {e.field(), e.message()};
    }
    return {};
}

struct Rule {
    const char* what;
    std::function<void(Model&)> pass_it_then_break; // on the model below
    std::string field;
    const char* message; // a part of the message
};

void check_rules(const Model& valid, const std::vector<Rule>& rules) {
    REQUIRE(refusal(valid).field.empty());
    for (const Rule& r : rules) {
        INFO(r.what);
        Model m = valid;
        r.pass_it_then_break(m);
        const Refusal got = refusal(m);
        CHECK(got.field == r.field);
        CHECK_THAT(got.message, Catch::Contains(r.message));
    }
}

} // namespace

TEST_CASE("The test B-reps are valid", "[model][brep]") {
    CHECK(refusal(test::plate_with_hole()).field.empty());
    CHECK(refusal(test::revolved(1)).field.empty());
    CHECK(refusal(test::revolved(0)).field.empty());
}

TEST_CASE("validate_brep refuses each broken vertex, curve and edge rule by field",
          "[model][brep]") {
    const std::vector<Rule> rules = {
        {"vertex NaN", [](Model& m) { m.brep.vertices[2].point.y = kNaN; },
         "brep.vertices[2].point[1]", "not a finite number"},
        {"vertex beyond the coordinate limit", [](Model& m) { m.brep.vertices[2].point.z = 1e300; },
         "brep.vertices[2].point[2]", "within"},
        {"vertex tolerance negative", [](Model& m) { m.brep.vertices[0].tolerance = -1; },
         "brep.vertices[0].tolerance", "tolerance -1"},
        {"curve degree 0", [](Model& m) { m.brep.curves[1].degree = 0; }, "brep.curves[1].degree",
         "outside 1..9"},
        {"curve with too few points", [](Model& m) { m.brep.curves[1].degree = 2; },
         "brep.curves[1].points", "too few for degree 2"},
        {"knot count", [](Model& m) { m.brep.curves[1].knots.pop_back(); }, "brep.curves[1].knots",
         "expected 4 numbers, got 3"},
        {"knots decrease",
         [](Model& m) {
             m.brep.curves[1].knots = {0, 0, 1, 0.5};
         },
         "brep.curves[1].knots[3]", "knots decrease"},
        {"empty domain",
         [](Model& m) {
             m.brep.curves[1].knots = {0, 0.5, 0.5, 1};
         },
         "brep.curves[1].knots", "empty domain"},
        {"multiplicity above degree+1",
         [](Model& m) {
             BSplineCurve& c = m.brep.curves[1];
             c.points.insert(c.points.begin() + 1, c.points[0]);
             c.knots = {0, 0, 0, 1, 1};
         },
         "brep.curves[1].knots", "multiplicity 3"},
        {"curve point infinite", [](Model& m) { m.brep.curves[1].points[0].x = kInf; },
         "brep.curves[1].points[0]", "not a finite point"},
        {"curve coordinate too large", [](Model& m) { m.brep.curves[1].points[1].z = -1e200; },
         "brep.curves[1].points[1][2]", "beyond the limit"},
        {"weight zero",
         [](Model& m) {
             m.brep.curves[1].weights = {1, 0};
         },
         "brep.curves[1].weights[1]", "not a positive finite number"},
        {"weight huge",
         [](Model& m) {
             m.brep.curves[1].weights = {1e100, 1};
         },
         "brep.curves[1].weights[0]", "outside"},
        {"weight count", [](Model& m) { m.brep.curves[1].weights = {1}; }, "brep.curves[1].weights",
         "expected 2 numbers, got 1"},
        {"pcurve off the (u,v) plane", [](Model& m) { m.brep.pcurves[5].points[1].z = 0.5; },
         "brep.pcurves[5].points[1]", "z = 0.5"},
        {"pcurve degree", [](Model& m) { m.brep.pcurves[5].degree = 10; }, "brep.pcurves[5].degree",
         "outside 1..9"},
        {"edge curve index", [](Model& m) { m.brep.edges[3].curve = 8; }, "brep.edges[3].curve",
         "index 8 out of range 0..7"},
        {"edge curve index negative", [](Model& m) { m.brep.edges[3].curve = -2; },
         "brep.edges[3].curve", "index -2"},
        {"edge vertex index", [](Model& m) { m.brep.edges[3].end = 8; },
         "brep.edges[3].vertices[1]", "out of range 0..7"},
        {"range empty", [](Model& m) { m.brep.edges[3].t1 = 0; }, "brep.edges[3].range",
         "t0 must be below t1"},
        {"range NaN", [](Model& m) { m.brep.edges[3].t0 = kNaN; }, "brep.edges[3].range",
         "not finite"},
        {"range outside the curve", [](Model& m) { m.brep.edges[3].t1 = 1.01; },
         "brep.edges[3].range", "not inside the domain [0, 1] of curve 3"},
        {"edge tolerance infinite", [](Model& m) { m.brep.edges[3].tolerance = kInf; },
         "brep.edges[3].tolerance", "not a number in"},
        {"degenerate edge between two vertices", [](Model& m) { m.brep.edges[3].curve = -1; },
         "brep.edges[3].vertices", "a degenerate edge"},
        {"edge used by no face", [](Model& m) { m.brep.edges.push_back(m.brep.edges[0]); },
         "brep.edges[8]", "used by no face"},
    };
    check_rules(test::plate_with_hole(), rules);
}

TEST_CASE("validate_brep refuses each broken face, loop, shell and solid rule by field",
          "[model][brep]") {
    const std::string c2 = "brep.faces[0].loops[0].coedges[2]";
    const std::vector<Rule> rules = {
        {"surface index", [](Model& m) { m.brep.faces[0].surface = 1; }, "brep.faces[0].surface",
         "index 1 out of range 0..0"},
        {"no loop", [](Model& m) { m.brep.faces[0].loops.clear(); }, "brep.faces[0].loops",
         "at least one loop"},
        {"empty loop", [](Model& m) { m.brep.faces[0].loops[1].coedges.clear(); },
         "brep.faces[0].loops[1].coedges", "at least one coedge"},
        {"coedge edge index", [](Model& m) { m.brep.faces[0].loops[0].coedges[2].edge = 9; },
         (c2 + ".edge"), "index 9"},
        {"coedge pcurve index", [](Model& m) { m.brep.faces[0].loops[0].coedges[2].pcurve = -1; },
         (c2 + ".pcurve"), "index -1"},
        {"pcurve domain short of the edge's range",
         [](Model& m) {
             m.brep.pcurves[2].knots = {0, 0, 0.5, 0.5};
         },
         (c2 + ".pcurve"), "does not hold the range [0, 1] of edge 2"},
        {"chain broken in 3D",
         [](Model& m) {
             auto& ce = m.brep.faces[0].loops[0].coedges;
             std::swap(ce[1], ce[2]);
         },
         "brep.faces[0].loops[0].coedges[1]", "not a closed chain"},
        {"chain open in (u,v)", [](Model& m) { m.brep.pcurves[2].points[0].x = 0.99; },
         (c2 + ".pcurve"), "open in (u,v)"},
        {"pcurve outside the surface's domain",
         [](Model& m) {
             m.brep.pcurves[0].points[1].y = -0.05;
             m.brep.pcurves[1].points[0].y = -0.05;
             m.brep.vertices[1].tolerance = 1; // the chain closes in 3D
         },
         "brep.faces[0].loops[0].coedges[0].pcurve", "leaves the (u,v) domain [0, 1] x [0, 1]"},
        {"pcurve on two surfaces",
         [](Model& m) {
             m.surfaces.push_back(m.surfaces[0]);
             m.brep.faces.push_back(m.brep.faces[0]);
             m.brep.faces[1].surface = 1;
         },
         "brep.faces[1].loops[0].coedges[0].pcurve", "lies on surface 0"},
        {"shell face index", [](Model& m) { m.brep.shells[0].faces = {1}; },
         "brep.shells[0].faces[0]", "out of range 0..0"},
        {"empty shell", [](Model& m) { m.brep.shells[0].faces.clear(); }, "brep.shells[0].faces",
         "at least one face"},
        {"solid shell index",
         [](Model& m) {
             m.brep.solids.push_back({{3}, "s"});
         },
         "brep.solids[0].shells[0]", "out of range 0..0"},
        {"empty solid",
         [](Model& m) {
             m.brep.solids.push_back({{}, "s"});
         },
         "brep.solids[0].shells", "at least one shell"},
    };
    check_rules(test::plate_with_hole(), rules);
}

TEST_CASE("validate_brep checks seams: two uses of opposite directions, closed across the seam",
          "[model][brep]") {
    const std::string loop = "brep.faces[0].loops[0]";
    const std::vector<Rule> rules = {
        {"seam used three times",
         [](Model& m) {
             auto& ce = m.brep.faces[0].loops[0].coedges;
             ce.push_back(ce[1]);
         },
         (loop + ".coedges[4].edge"), "a third time"},
        {"seam used twice one way",
         [](Model& m) { m.brep.faces[0].loops[0].coedges[3].reversed = false; },
         (loop + ".coedges[3].edge"), "same direction"},
        {"both seam coedges on u = 0: open across the seam",
         [](Model& m) { m.brep.faces[0].loops[0].coedges[1].pcurve = 2; },
         (loop + ".coedges[1].pcurve"), "open in (u,v)"},
    };
    check_rules(test::revolved(1), rules);
    check_rules(test::revolved(0), rules);
    check_rules(
        test::revolved(0),
        {{"a degenerate edge's vertices differ",
          [](Model& m) {
              m.brep.vertices.push_back(m.brep.vertices[1]);
              m.brep.edges[1].end = 2;
          },
          "brep.edges[1].vertices", "a degenerate edge (no curve) starts and ends at one vertex"}});
}

TEST_CASE("validate_brep allows its documented slack and no more", "[model][brep]") {
    // An edge's range past its curve's domain by 1e-7 of it: rounding.
    Model m = test::plate_with_hole();
    m.brep.edges[3].t1 = 1 + 1e-7;
    CHECK(refusal(m).field.empty());
    m.brep.edges[3].t1 = 1 + 1e-5;
    CHECK(refusal(m).field == "brep.edges[3].range");

    // A (u,v) gap of 1e-7 of the domain's diagonal closes; one of 1e-5
    // (1e-4 model units) closes only if the vertex's tolerance covers it.
    m = test::plate_with_hole();
    // Pcurve 1 runs from (1, 0) to (1, 1), pcurve 2 from (1, 1) to (0, 1).
    m.brep.pcurves[2].points[0].y = 1 - 1e-7;
    CHECK(refusal(m).field.empty());
    m.brep.pcurves[2].points[0].y = 1 - 1e-5;
    m.brep.pcurves[1].points[1].y = 1 - 1e-5;
    CHECK(refusal(m).field.empty()); // both ends moved: closed
    m.brep.pcurves[1].points[1].y = 1;
    CHECK(refusal(m).field == "brep.faces[0].loops[0].coedges[2].pcurve");
    m.brep.vertices[2].tolerance = 1e-3;
    CHECK(refusal(m).field.empty());

    // A cone's loop without its degenerate edge: the (u,v) gap runs along
    // the pole, where the whole segment is the apex.
    m = test::revolved(0);
    auto& ce = m.brep.faces[0].loops[0].coedges;
    ce.erase(ce.begin() + 2);
    m.brep.faces.push_back(test::revolved(0).brep.faces[0]); // uses the degenerate edge
    CHECK(refusal(m).field.empty());
    // The same gap on the cylinder is the top circle: refused.
    m = test::revolved(1);
    m.brep.faces.push_back(m.brep.faces[0]);
    m.brep.faces[0].loops[0].coedges.erase(m.brep.faces[0].loops[0].coedges.begin() + 2);
    CHECK(refusal(m).field == "brep.faces[0].loops[0].coedges[2].pcurve");

    // A pcurve past the surface's domain by 1e-7 of it.
    m = test::plate_with_hole();
    m.brep.pcurves[0].points[1].y = m.brep.pcurves[1].points[0].y = -1e-7;
    CHECK(refusal(m).field.empty());
}

TEST_CASE("validate_brep refuses sizes past ModelLimits", "[model][brep][hostile]") {
    ModelLimits limits;
    limits.max_brep_items = 7;
    Refusal r = refusal(test::plate_with_hole(), limits);
    CHECK(r.field == "brep.vertices");
    CHECK(r.message == "8 vertices exceed the limit of 7");
    limits = {};
    limits.max_curve_points = 1;
    r = refusal(test::plate_with_hole(), limits);
    CHECK(r.field == "brep.curves[0].points");
    CHECK(r.message == "2 control points exceed the limit of 1");
    limits = {};
    limits.max_brep_items = 4; // 2 vertices, 3 curves and edges, 4 pcurves, 5 coedges
    Model m = test::revolved(1);
    m.brep.faces[0].loops.push_back({{m.brep.faces[0].loops[0].coedges[0]}});
    r = refusal(m, limits);
    CHECK(r.field == "brep.faces");
    CHECK(r.message == "5 coedges exceed the limit of 4");
}
