// SPDX-License-Identifier: MIT
// Boehm knot insertion and Bezier extraction (paper section 4): the extracted
// patches reproduce the B-spline surface to rounding.
#include "random_surface.h"
#include "test_util.h"

#include <seamless/model/model.h>
#include <seamless/spline/knot_insertion.h>

#include <catch2/catch.hpp>

using namespace seamless;

namespace {

// Largest distance between surface and its Bezier patches at `samples` random
// parameters, relative to d_max of the control points.
double extraction_error(const BSplineSurface& s, std::mt19937& rng, int samples) {
    const auto patches = bezier_patches(s, 0);
    REQUIRE(static_cast<int>(patches.size()) == bezier_patch_count(s));
    const double dmax = std::max(control_box(s).max_extent(), 1e-300);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    double worst = 0;
    for (int n = 0; n < samples; ++n) {
        const BezierPatch& b = patches[rng() % patches.size()];
        double sl = U(rng), tl = U(rng);
        SurfacePoint pb = evaluate(b, sl, tl);
        SurfacePoint ps = evaluate(s, b.u_at(sl), b.v_at(tl));
        worst = std::max(worst, distance(pb.point, ps.point) / dmax);
        // Derivatives: local (s,t) derivative = surface derivative * span length.
        Vec3 du = ps.du * (b.u1 - b.u0), dv = ps.dv * (b.v1 - b.v0);
        double scale = std::max({norm(du), norm(dv), 1.0}) * dmax;
        CHECK(distance(pb.du, du) <= 1e-9 * scale);
        CHECK(distance(pb.dv, dv) <= 1e-9 * scale);
    }
    return worst;
}

} // namespace

TEST_CASE("Bezier extraction reproduces the teapot", "[knot_insertion][heavy]") {
    const Model m = load_model(test::model_path("teapot.json"));
    REQUIRE(bezier_patches(m).size() == 32);
    std::mt19937 rng(1);
    for (const BSplineSurface& s : m.surfaces) CHECK(extraction_error(s, rng, 1000) <= 1e-12);
}

TEST_CASE("Bezier extraction reproduces random surfaces of degree 1 to 5",
          "[knot_insertion][heavy]") {
    std::mt19937 rng(2);
    for (int p = 1; p <= 5; ++p)
        for (int q = 1; q <= 5; ++q)
            for (bool clamped : {true, false})
                for (bool rational : {false, true}) {
                    test::RandomSurfaceOptions o{p, q, clamped, rational};
                    BSplineSurface s = test::random_surface(rng, o);
                    INFO("degree " << p << "x" << q << (clamped ? " clamped" : " unclamped")
                                   << (rational ? " rational" : ""));
                    CHECK(extraction_error(s, rng, 1000) <= 1e-12);
                }
}

TEST_CASE("Bezier extraction of the bundled models with interior and repeated knots",
          "[knot_insertion]") {
    std::mt19937 rng(3);
    for (const char* name : {"repeated_knot.json", "torus.json", "torus_exact.json",
                             "quarter_cylinder.json", "bilinear.json", "extreme_weights.json"}) {
        INFO(name);
        const Model m = load_model(test::model_path(name));
        for (const BSplineSurface& s : m.surfaces) CHECK(extraction_error(s, rng, 1000) <= 1e-12);
    }
}

TEST_CASE("Patches tile the domain and abut along shared knot lines", "[knot_insertion]") {
    const Model m = load_model(test::model_path("repeated_knot.json"));
    const auto patches = bezier_patches(m.surfaces[0], 0);
    double area = 0;
    for (const BezierPatch& b : patches) {
        CHECK(b.u0 < b.u1);
        CHECK(b.v0 < b.v1);
        area += (b.u1 - b.u0) * (b.v1 - b.v0);
    }
    const BSplineSurface& s = m.surfaces[0];
    CHECK(area == Approx((s.u_max() - s.u_min()) * (s.v_max() - s.v_min())));
    // Neighbours in u share their boundary row exactly (up to rounding of insertion).
    for (const BezierPatch& a : patches)
        for (const BezierPatch& b : patches)
            if (a.u1 == b.u0 && a.v0 == b.v0)
                for (int j = 0; j <= a.q; ++j)
                    CHECK(distance(a.point(a.p, j), b.point(0, j)) <= 1e-14);
}

TEST_CASE("Boehm insertion leaves the surface unchanged", "[knot_insertion]") {
    std::mt19937 rng(4);
    BSplineSurface s = test::random_surface(rng, {3, 2, false, true});
    HomogeneousNet net = homogeneous_net(s);
    const double t = 0.5 * (s.u_min() + s.u_max());
    insert_knot_u(net, t);
    insert_knot_v(net, s.v_min() + 0.3 * (s.v_max() - s.v_min()));
    BSplineSurface r = s;
    r.size_u = net.rows;
    r.size_v = net.cols;
    r.knots_u = net.knots_u;
    r.knots_v = net.knots_v;
    r.points.clear();
    r.weights.clear();
    for (const HPoint& h : net.cp) {
        r.points.push_back(h.point());
        r.weights.push_back(h.w);
    }
    std::uniform_real_distribution<double> U(0, 1);
    for (int n = 0; n < 200; ++n) {
        double u = s.u_min() + U(rng) * (s.u_max() - s.u_min());
        double v = s.v_min() + U(rng) * (s.v_max() - s.v_min());
        CHECK(distance(evaluate(s, u, v).point, evaluate(r, u, v).point) <= 1e-12);
    }
}
