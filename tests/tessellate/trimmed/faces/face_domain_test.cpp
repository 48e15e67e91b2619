// SPDX-License-Identifier: MIT
// The face's (u,v) domain rescaled by its surface's metric and curvature
// (face_domain.h): on a torus, which curves about six times as much across its
// tube as around its axis on average, the triangles are longer around the
// axis than across the tube, as a deviation-driven mesh's should be.
#include <tessellate/trimmed/brep_cases.h>

#include <seamless/tessellate/tessellation.h>

#include <catch2/catch.hpp>

#include <cmath>

using namespace seamless;
using namespace seamless::test;

TEST_CASE("face domain: a torus's triangles are long around its axis, where it curves less",
          "[brep]") {
    const BRepCase c = torus_solid();
    TessellationOptions o;
    o.threads = 1;
    const Tessellation t = tessellate(c.model, o);
    // Each triangle side split into its part around the axis (along the
    // circle about z through its midpoint) and the rest, across the tube.
    double around = 0, across = 0;
    for (const auto& tri : t.mesh.triangles)
        for (int k = 0; k < 3; ++k) {
            const Vec3 a = t.mesh.positions[tri[k]], b = t.mesh.positions[tri[(k + 1) % 3]];
            const Vec3 m = 0.5 * (a + b);
            const Vec3 tangent = normalize(Vec3{-m.y, m.x, 0});
            const double along = std::abs(dot(b - a, tangent));
            around += along;
            across += std::sqrt(std::max(0.0, dot(b - a, b - a) - along * along));
        }
    INFO(t.mesh.triangle_count() << " triangles; around / across " << around / across);
    REQUIRE(t.mesh.triangle_count() > 100);
    // Scaled by the metric alone the triangles are about as long both ways.
    CHECK(around / across > 1.8);
}
