// SPDX-License-Identifier: MIT
// A face whose loop touches itself along a length (the IGES spring's face
// DE25: an end cap's edge runs along the face's side edge, the face between
// them of no width): the cap edge's pcurve wobbles across the side within
// its tolerance, which re-splitting never mends; the face is meshed, its
// crossing points moved onto the face's side in (u,v) only.
#include <tessellate/mesh_properties.h>
#include <tessellate/trimmed/brep_builder.h>

#include <seamless/base/check.h>
#include <seamless/tessellate/tessellation.h>

#include <catch2/catch.hpp>

#include <cmath>

using namespace seamless;
using namespace seamless::test;

namespace {

constexpr Vec3 kX{1, 0, 0}, kY{0, 1, 0};
const PlaneFrame kPlane{{0, 0, 0}, kX, kY};

// The rectangle [0, 1] x [0.5, 1] whose loop runs down x = 0 from (0, 1) to
// (0, 0) and back up along it, wobbling +-wobble in x, before turning to
// (1, 0.5): a strip of no width below y = 0.5.
Model touching_face(double wobble, double cap_tolerance) {
    BRepBuilder b;
    const int s = b.surface(kPlane.surface(-0.5, 1.5, -0.5, 1.5), "plane");
    const int top_left = b.vertex({0, 1, 0}), origin = b.vertex({0, 0, 0}),
              right = b.vertex({1, 0.5, 0}), top_right = b.vertex({1, 1, 0});
    const BSplineCurve side = nurbs_line({0, 1, 0}, {0, 0, 0});
    // Degree 1: its kinks are polyline points, alternately either side.
    BSplineCurve cap;
    cap.degree = 1;
    constexpr int kAlong = 12;
    for (int i = 0; i <= kAlong; ++i) {
        const double x = i == 0 ? 0 : i % 2 ? wobble : -wobble;
        cap.points.push_back({x, 0.5 * i / kAlong, 0});
    }
    cap.points.push_back({1, 0.5, 0});
    cap.knots.push_back(0);
    for (size_t i = 0; i < cap.points.size(); ++i) cap.knots.push_back(static_cast<double>(i));
    cap.knots.push_back(static_cast<double>(cap.points.size() - 1));
    const BSplineCurve up = nurbs_line({1, 0.5, 0}, {1, 1, 0});
    const BSplineCurve back = nurbs_line({1, 1, 0}, {0, 1, 0});
    b.new_loop();
    b.use(b.edge(side, top_left, origin), false, kPlane.pcurve(side));
    b.use(b.edge(cap, origin, right, cap_tolerance), false, kPlane.pcurve(cap));
    b.use(b.edge(up, right, top_right), false, kPlane.pcurve(up));
    b.use(b.edge(back, top_right, top_left), false, kPlane.pcurve(back));
    b.face(s, false, "#touching");
    return b.finish(false, "touching");
}

double area(const TriangleMesh& m) {
    double a = 0;
    for (const auto& t : m.triangles)
        a += 0.5 * norm(cross(m.positions[t[1]] - m.positions[t[0]],
                              m.positions[t[2]] - m.positions[t[0]]));
    return a;
}

} // namespace

TEST_CASE("trimmed faces: a loop touching itself along a length within tolerance is meshed",
          "[brep]") {
    const Model m = touching_face(1e-4, 1e-3);
    const Tessellation t = tessellate(m, {});
    CHECK(t.stats.brep.faces_left_out == 0);
    const MeshReport r = analyse_mesh(t.mesh, 1);
    CHECK(r.zero_area == 0);
    CHECK(r.nonmanifold_edges == 0);
    CHECK(r.misoriented_edges == 0);
    CHECK(r.euler() == 1);
    // The rectangle, and the strip's slivers of about the wobble's width.
    CHECK(std::abs(area(t.mesh) - 0.5) < 1e-3);
}

TEST_CASE("trimmed faces: loops crossing farther apart than their tolerance still fail", "[brep]") {
    // The same wobble with a tolerance ten times below it: a real crossing.
    const Model m = touching_face(1e-4, 1e-5);
    REQUIRE_THROWS_WITH(tessellate(m, {}), Catch::Contains("#touching"));
}
