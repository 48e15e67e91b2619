// SPDX-License-Identifier: MIT
// An edge's polyline: its chords within the deviation of the 3D curve and
// its tangent turning within the angle per segment, ends at its vertices;
// halving inserts every midpoint and keeps the rest.
#include <tessellate/trimmed/brep_builder.h>

#include <seamless/base/segment_distance.h>
#include <seamless/tessellate/trimmed/edge_discretisation.h>

#include <catch2/catch.hpp>

#include <cmath>

using namespace seamless;
using namespace seamless::test;

TEST_CASE("edge discretisation: a circle's chords within D, its turning within the angle",
          "[brep]") {
    BRepBuilder b;
    const int v = b.vertex({2, 0, 0});
    const int e = b.edge(nurbs_circle({}, 2, {1, 0, 0}, {0, 1, 0}), v, v);
    const BRep& brep = b.m.brep;
    for (const auto& [D, angle] : {std::pair{1e-2, 3.0}, {1e-4, 3.0}, {1.0, 0.3}}) {
        const EdgePolyline line = discretise_edge(brep, e, {}, {D, angle});
        REQUIRE(line.t.size() >= 4);
        CHECK(line.points.front() == brep.vertices[v].point);
        CHECK(line.points.back() == brep.vertices[v].point);
        CHECK(!line.limited);
        CHECK(line.deviation <= D);
        for (size_t k = 1; k < line.t.size(); ++k) {
            REQUIRE(line.t[k] > line.t[k - 1]);
            for (int j = 1; j < 10; ++j) {
                const double t = line.t[k - 1] + (line.t[k] - line.t[k - 1]) * j / 10;
                const Vec3 p = evaluate(brep.curves[0], t).point;
                CHECK(point_segment_distance(p, line.points[k - 1], line.points[k]) <= D);
            }
            // The chord of a circular arc turns by its central angle.
            const double turn = 2 * std::asin(distance(line.points[k - 1], line.points[k]) / 4);
            CHECK(turn <= angle + 1e-12);
        }
        EdgePolyline halved = line;
        halve_segments(brep, e, halved);
        CHECK(halved.t.size() == 2 * line.t.size() - 1);
        for (size_t k = 0; k < line.t.size(); ++k) CHECK(halved.t[2 * k] == line.t[k]);
    }
}

TEST_CASE("edge discretisation: a curve standing still between two kinks leaves no zero-length "
          "segment",
          "[brep]") {
    // A composite curve's zero-length piece (IGES 102 after sewing): the
    // degree-1 curve stands still over [1, 2], whose ends are both kinks.
    BRepBuilder b;
    const int v0 = b.vertex({0, 0, 0}), v1 = b.vertex({2, 0, 0});
    BSplineCurve c;
    c.degree = 1;
    c.knots = {0, 0, 1, 2, 3, 3};
    c.points = {{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {2, 0, 0}};
    const int e = b.edge(c, v0, v1);
    const BRep& brep = b.m.brep;
    const auto no_zero_length = [](const EdgePolyline& line) {
        for (size_t k = 1; k < line.points.size(); ++k)
            if (!(distance(line.points[k - 1], line.points[k]) > 0)) return false;
        return true;
    };
    EdgePolyline line = discretise_edge(brep, e, {}, {1e-3, 0.5});
    CHECK(line.points.front() == brep.vertices[v0].point);
    CHECK(line.points.back() == brep.vertices[v1].point);
    CHECK(no_zero_length(line));
    // Halving does not put a point on the still piece either.
    for (int round = 0; round < 3; ++round) {
        halve_segments(brep, e, line);
        CHECK(no_zero_length(line));
    }
}

TEST_CASE("edge discretisation: a pole written to a file's precision has the surface's normal",
          "[brep]") {
    // The planar triangle P(u, v) = v (2u - 1, 1, 0) collapsed at v = 0, its
    // pole's second control point 1e-10 off the first across the plane (as
    // trj3_s1-al's half-disks #1303/#1304 are written): dP/du at the pole is
    // that rounding, and dP/du x dP/dv lies in the plane.
    BSplineSurface s;
    s.degree_u = s.degree_v = 1;
    s.size_u = s.size_v = 2;
    s.knots_u = s.knots_v = {0, 0, 1, 1};
    s.points = {{0, 0, 0}, {-1, 1, 0}, {0, 0, 1e-10}, {1, 1, 0}};
    const FaceSurface surface(s);
    const Vec3 inward{0.5, 0.5, 0};
    for (double u : {0.0, 0.5, 1.0})
        CHECK(std::abs(std::abs(unit_normal(surface, {u, 0, 0}, inward).z) - 1) < 1e-6);
    // The edge from the pole to (1, 1, 0), along u = 1: its normal turns by
    // nothing, so it is one chord, not split to the depth limit at the pole.
    BRepBuilder b;
    const int pole = b.vertex({0, 0, 0}), corner = b.vertex({1, 1, 0});
    const BSplineCurve line = nurbs_line({0, 0, 0}, {1, 1, 0});
    const int e = b.edge(line, pole, corner);
    const BSplineCurve pcurve = nurbs_line({1, 0, 0}, {1, 1, 0});
    const EdgePolyline polyline =
        discretise_edge(b.m.brep, e, {{surface, &pcurve, 1e-7, inward}}, {1e-3, 0.5});
    CHECK(!polyline.limited);
    CHECK(polyline.t.size() == 2);
}
