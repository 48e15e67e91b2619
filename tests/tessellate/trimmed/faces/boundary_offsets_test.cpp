// SPDX-License-Identifier: MIT
// Boundary points off the surface (FaceDomain::offset): a face whose edges'
// curves run a known offset below D off its surface, each edge claiming a
// tolerance of five times D (files claim loose tolerances), is meshed
// within D: a triangle may take from the surface what its corners' offsets
// force, not what the tolerances allow. And a polar lune, whose needles at
// the pole are mended inside it rather than by halving its meridians.
#include <tessellate/trimmed/brep_builder.h>

#include <seamless/tessellate/tessellation.h>
#include <seamless/tessellate/trimmed/faces/face_domain.h>

#include <catch2/catch.hpp>

#include <cmath>

using namespace seamless;
using namespace seamless::test;

namespace {

constexpr Vec3 kX{1, 0, 0}, kY{0, 1, 0}, kZ{0, 0, 1};

// Largest distance from the unit sphere of the triangles' points on a
// barycentric grid: the flat triangles' deviation, measured exactly.
double sphere_deviation(const TriangleMesh& m) {
    constexpr int kLevel = 12;
    double worst = 0;
    for (const auto& t : m.triangles)
        for (int i = 0; i <= kLevel; ++i)
            for (int j = 0; i + j <= kLevel; ++j) {
                const Vec3 p = (i * m.positions[t[0]] + j * m.positions[t[1]] +
                                (kLevel - i - j) * m.positions[t[2]]) /
                               double(kLevel);
                worst = std::max(worst, std::abs(norm(p) - 1));
            }
    return worst;
}

// A lune of the unit sphere: u in [0, u1], v from the south pole (a
// degenerate edge) to the parallel at v1 (1: the equator), its edges' curves
// at radius 1 + shift.
Model lune(double u1, double v1, double shift, double tolerance) {
    BRepBuilder b;
    const double r = 1 + shift;
    const BSplineCurve profile = nurbs_half_circle({}, r, kX, kZ);
    const Vec3 top = evaluate_point(profile, v1);
    const BSplineCurve parallel_curve = nurbs_circle({0, 0, top.z}, top.x, kX, kY);
    const Vec3 side = evaluate_point(parallel_curve, u1);
    const int south = b.vertex({0, 0, -r}), e0 = b.vertex(top), e1 = b.vertex(side);
    const int pole = b.degenerate_edge(south, 0, u1);
    auto edge = [&](const BSplineCurve& c, int from, int to, double t1) {
        const int id = b.edge(c, from, to, tolerance);
        b.m.brep.edges[id].t1 = t1;
        return id;
    };
    const Vec3 towards = normalize(Vec3{side.x, side.y, 0});
    const int m0 = edge(profile, south, e0, v1),
              m1 = edge(nurbs_half_circle({}, r, towards, kZ), south, e1, v1),
              parallel = edge(parallel_curve, e0, e1, u1);
    const int s = b.surface(sphere_surface({}, 1), "sphere");
    auto line = [](Vec3 a, Vec3 c, double t1) {
        BSplineCurve k = nurbs_line(a, c);
        k.knots = {0, 0, t1, t1};
        return k;
    };
    b.new_loop();
    b.use(pole, false, line({0, 0, 0}, {u1, 0, 0}, u1));
    b.use(m1, false, line({u1, 0, 0}, {u1, v1, 0}, v1));
    b.use(parallel, true, line({0, v1, 0}, {u1, v1, 0}, u1));
    b.use(m0, true, line({0, 0, 0}, {0, v1, 0}, v1));
    b.face(s, false, "#lune");
    return b.finish(false, "lune");
}

} // namespace

TEST_CASE("boundary offsets: a face's boundary points are measured off its surface", "[brep]") {
    const double shift = -5e-4;
    const Model m = lune(1, 1, shift, 5e-3);
    std::vector<EdgePolyline> lines(m.brep.edges.size());
    for (size_t e = 0; e < lines.size(); ++e)
        lines[e] = discretise_edge(m.brep, static_cast<int>(e), {}, {1e-3, 0.5});
    const FaceDomain d = face_domain(m, lines, 0);
    REQUIRE(static_cast<int>(d.offset.size()) == d.size());
    for (int i = 0; i < d.boundary_points; ++i)
        CHECK(std::abs(d.offset[i] - std::abs(shift)) < 1e-12);
}

TEST_CASE("boundary offsets: loose edge tolerances leave the mesh within D", "[brep]") {
    const double D = 1e-3;
    // Inward the chords' sag adds to the offset; outward it takes from it.
    for (double shift : {-0.5 * D, 0.5 * D, 0.8 * D}) {
        INFO("shift " << shift);
        TessellationOptions o;
        o.tolerance = D;
        o.threads = 1;
        const Tessellation t = tessellate(lune(0.5, 1, shift, 5 * D), o);
        CHECK(t.stats.brep.edges_above_tolerance == 3);
        // The stats report the measured offset, not the claimed tolerance.
        CHECK(std::abs(t.stats.brep.max_edge_offset - std::abs(shift)) < 1e-12);
        CHECK(t.stats.brep.above_tolerance == 0);
        CHECK(t.stats.brep.max_deviation <= D);
        CHECK(sphere_deviation(t.mesh) <= D);
    }
}

TEST_CASE("boundary offsets: a gap above D is reported and the mesh stays within D beyond it",
          "[brep]") {
    // Edge curves 3 D off the sphere: no mesh of the face is within D of it
    // at its boundary; the stats and the warning say how far, and inside the
    // face the triangles come back to the surface.
    const double D = 1e-3, shift = 3 * D;
    TessellationOptions o;
    o.tolerance = D;
    o.threads = 1;
    const Tessellation t = tessellate(lune(0.5, 1, shift, 1e-9), o);
    const BRepStats& b = t.stats.brep;
    CHECK(b.edges_above_tolerance == 0);
    CHECK(std::abs(b.max_edge_offset - shift) < 1e-12);
    const double measured = sphere_deviation(t.mesh);
    CHECK(measured >= shift * (1 - 1e-9));
    CHECK(measured <= shift + D);
    CHECK(b.max_deviation <= shift + D);
    REQUIRE(b.warnings.size() == 1);
    CHECK(b.warnings[0].find("lie up to 0.003 off their faces") != std::string::npos);
    CHECK(b.warnings[0].find("at least that") != std::string::npos);
}

TEST_CASE("boundary offsets: a polar lune's needles at the pole are mended inside it", "[brep]") {
    // Their circumcentres fall beside the pole's degenerate edge: halving a
    // meridian towards the pole, as encroachment would, mends nothing.
    for (double D : {1e-2, 3e-3, 1e-3}) {
        INFO("D " << D);
        TessellationOptions o;
        o.tolerance = D;
        o.threads = 1;
        const Tessellation t = tessellate(lune(1, 0.2, 0, 1e-9), o);
        CHECK(t.stats.brep.above_tolerance == 0);
        CHECK(t.stats.brep.max_deviation <= D);
        CHECK(sphere_deviation(t.mesh) <= D);
    }
}
