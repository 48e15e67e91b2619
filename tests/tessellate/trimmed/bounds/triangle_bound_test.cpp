// SPDX-License-Identifier: MIT
#include <tessellate/trimmed/bounds/bound_cases.h>

#include <seamless/tessellate/trimmed/bounds/chord_bound.h>
#include <seamless/tessellate/trimmed/bounds/triangle_bound.h>
#include <seamless/tessellate/trimmed/face_surface.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <vector>

using namespace seamless;

namespace {

// A cylinder of radius 1 and height 2 as OpenCASCADE writes one.
BSplineSurface cylinder() {
    return test::revolved_segment(1, 0, 1, 2);
}

// A bicubic B-spline with random heights over [0,3]^2 and interior knots of
// multiplicity 1, 2 (C1) and 3 (C0: a real crease) in u.
BSplineSurface creased(std::mt19937& rng) {
    std::uniform_real_distribution<double> h(-0.5, 0.5);
    BSplineSurface s;
    s.degree_u = s.degree_v = 3;
    s.knots_u = {0, 0, 0, 0, 1, 1.5, 1.5, 2, 2, 2, 3, 3, 3, 3};
    s.knots_v = {0, 0, 0, 0, 1, 2, 3, 3, 3, 3};
    s.size_u = static_cast<int>(s.knots_u.size()) - 4;
    s.size_v = static_cast<int>(s.knots_v.size()) - 4;
    for (int i = 0; i < s.size_u; ++i)
        for (int j = 0; j < s.size_v; ++j)
            s.points.push_back({3.0 * i / (s.size_u - 1), 3.0 * j / (s.size_v - 1), h(rng)});
    return s;
}

// Random triangles of size `size` with corners in [lo, hi]^2 of (u,v), on
// `surface` (the one `bound` is for), their corners moved off it by up to
// `lift`: the bound is finite and holds at every sampled point.
struct TriangleCheck {
    const TriangleBound& bound;
    std::function<Vec3(double, double)> surface;
    std::array<double, 2> lo, hi;
    double size, lift = 0;
};

// Returns the median ratio bound / largest sampled distance.
double check_triangles(const TriangleCheck& t, std::mt19937& rng) {
    std::uniform_real_distribution<double> U(t.lo[0], t.hi[0] - t.size),
        V(t.lo[1], t.hi[1] - t.size), d(0, t.size), l(-t.lift, t.lift), b(0, 1);
    std::vector<double> ratios;
    for (int n = 0; n < 200; ++n) {
        const double u = U(rng), v = V(rng);
        std::array<UV, 3> x;
        std::array<Vec3, 3> Q;
        for (int k = 0; k < 3; ++k) {
            x[k] = {u + d(rng), v + d(rng)};
            Q[k] = t.surface(x[k][0], x[k][1]);
            if (t.lift > 0) Q[k] = Q[k] + Vec3{l(rng), l(rng), l(rng)};
        }
        const double B = t.bound(x, Q);
        REQUIRE(std::isfinite(B));
        // With a cutoff (a running maximum): still a bound, at most the
        // larger of the two, and the full one wherever it exceeds the cutoff.
        double cut[3];
        for (int c = 0; c < 3; ++c) {
            const double cutoff = B * (0.5 + 0.5 * c);
            cut[c] = t.bound(x, Q, cutoff);
            CHECK(cut[c] <= std::max(B, cutoff));
            if (cut[c] > cutoff) CHECK(cut[c] == B);
        }
        double largest = 0;
        for (int m = 0; m < 60; ++m) {
            double a = b(rng), c = b(rng);
            if (a + c > 1) a = 1 - a, c = 1 - c;
            const double lam[3] = {1 - a - c, a, c};
            const double pu = lam[0] * x[0][0] + lam[1] * x[1][0] + lam[2] * x[2][0];
            const double pv = lam[0] * x[0][1] + lam[1] * x[1][1] + lam[2] * x[2][1];
            const Vec3 L = lam[0] * Q[0] + lam[1] * Q[1] + lam[2] * Q[2];
            largest = std::max(largest, distance(t.surface(pu, pv), L));
        }
        REQUIRE(largest <= B);
        for (double c : cut) REQUIRE(largest <= c);
        if (largest > 0) ratios.push_back(B / largest);
    }
    std::sort(ratios.begin(), ratios.end());
    return ratios.empty() ? 0 : ratios[ratios.size() / 2];
}

// Over the domain of s, the surface as evaluated.
double check_triangles(const BSplineSurface& s, double size, double lift, std::mt19937& rng) {
    const TriangleBound bound(s);
    return check_triangles({bound,
                            [&](double u, double v) { return evaluate(s, u, v).point; },
                            {s.u_min(), s.v_min()},
                            {s.u_max(), s.v_max()},
                            size,
                            lift},
                           rng);
}

} // namespace

TEST_CASE("the triangle bound holds on a rational cylinder across its double knots", "[heavy]") {
    std::mt19937 rng(3);
    for (double size : {0.3, 0.05, 0.005}) {
        const double ratio = check_triangles(cylinder(), size, 0, rng);
        INFO("size " << size << ": median bound / largest sampled distance " << ratio);
        // Measured 1.15 to 1.18 (the hull of the degree 2 (n + 1)
        // coefficients against the sampled largest, itself a lower estimate).
        CHECK(ratio < 2);
    }
}

TEST_CASE("the triangle bound holds on a bicubic B-spline with C1 and C0 knot lines", "[heavy]") {
    std::mt19937 rng(5);
    const BSplineSurface s = creased(rng);
    for (double size : {1.0, 0.2, 0.02}) {
        const double ratio = check_triangles(s, size, 0, rng);
        INFO("size " << size << ": median bound / largest sampled distance " << ratio);
        CHECK(ratio < 2); // measured 1.09 to 1.11
    }
}

TEST_CASE("the triangle bound holds on a rational degree 9 x 9 B-spline with many knot spans",
          "[heavy]") {
    // As ksu_c_el's blends: many spans under each triangle, the blossoms at
    // the highest degree the restriction takes.
    std::mt19937 rng(29);
    std::uniform_real_distribution<double> h(-0.3, 0.3), w(0.5, 2);
    BSplineSurface s;
    s.degree_u = s.degree_v = 9;
    s.knots_u.assign(10, 0.0), s.knots_v.assign(10, 0.0);
    for (int k = 1; k < 6; ++k) s.knots_u.push_back(k / 6.0), s.knots_v.push_back(k / 6.0);
    for (int k = 0; k < 10; ++k) s.knots_u.push_back(1), s.knots_v.push_back(1);
    s.size_u = s.size_v = static_cast<int>(s.knots_u.size()) - 10;
    for (int i = 0; i < s.size_u; ++i)
        for (int j = 0; j < s.size_v; ++j) {
            s.points.push_back({double(i) / (s.size_u - 1), double(j) / (s.size_v - 1), h(rng)});
            s.weights.push_back(w(rng));
        }
    for (double size : {0.5, 0.1, 0.01}) {
        const double ratio = check_triangles(s, size, 0, rng);
        INFO("size " << size << ": median bound / largest sampled distance " << ratio);
        CHECK(ratio >= 1);
    }
}

TEST_CASE("the triangle bound counts corners off the surface in full") {
    std::mt19937 rng(11);
    const BSplineSurface s = cylinder();
    check_triangles(s, 0.01, 1e-3, rng);
    const TriangleBound bound(s);
    const std::array<UV, 3> x{UV{0.1, 0.1}, UV{0.11, 0.1}, UV{0.1, 0.11}};
    std::array<Vec3, 3> Q;
    for (int k = 0; k < 3; ++k) Q[k] = evaluate(s, x[k][0], x[k][1]).point;
    const double on = bound(x, Q);
    Q[1] = Q[1] + Vec3{0, 0, 0.25};
    CHECK(bound(x, Q) >= 0.25);
    CHECK(bound(x, Q) <= on + 0.25 + 1e-12);
}

TEST_CASE("the chord bound holds on a rational quarter circle and is tight") {
    BSplineCurve c;
    c.degree = 2;
    c.knots = {0, 0, 0, 1, 1, 1};
    c.points = {{1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    c.weights = {1, std::sqrt(0.5), 1};
    const ChordBound bound(c);
    for (double h : {0.5, 0.1, 0.01}) {
        const double ta = 0.3, tb = 0.3 + h;
        const Vec3 Pa = evaluate(c, ta).point, Pb = evaluate(c, tb).point;
        const double B = bound(ta, tb, Pa, Pb);
        double largest = 0;
        for (int k = 1; k < 100; ++k) {
            const double l = k / 100.0;
            largest =
                std::max(largest, distance(evaluate(c, ta + l * h).point, (1 - l) * Pa + l * Pb));
        }
        INFO("h " << h << ": bound " << B << ", sampled " << largest);
        CHECK(largest <= B);
        CHECK(B <= 4 * largest);
    }
}

namespace {

// With the face's surface as the trimmed pipeline evaluates it (FaceSurface:
// wrapped where closed, its tangent plane beyond an open side).
void check_face_triangles(const BSplineSurface& s, std::array<double, 2> lo,
                          std::array<double, 2> hi, double size, std::mt19937& rng) {
    const FaceSurface face(s);
    const TriangleBound bound(s, face.closed_u(), face.closed_v());
    check_triangles({bound,
                     [&](double u, double v) {
                         return face.at({u, v, 0}).point;
                     },
                     lo, hi, size},
                    rng);
}

} // namespace

TEST_CASE("the triangle bound holds across a closed surface's seam", "[heavy]") {
    std::mt19937 rng(13);
    // The cylinder is closed in u (domain [0, 1]): triangles over [-0.3, 2.3].
    for (double size : {0.2, 0.02})
        check_face_triangles(cylinder(), {-0.3, 0}, {2.3, 2}, size, rng);
}

TEST_CASE("the triangle bound holds past an open side, against the tangent plane there",
          "[heavy]") {
    std::mt19937 rng(19);
    const BSplineSurface s = creased(rng);
    // A pcurve a rounding past the domain [0,3]^2, and a loop well beyond it:
    // triangles across the side u = 3 and across the corner (0, 0).
    for (double out : {1e-9, 1e-6, 0.05})
        for (double size : {0.3, 0.01}) {
            check_face_triangles(s, {3 - 2 * size, 1}, {3 + out, 2}, size, rng);
            check_face_triangles(s, {-out, -out}, {2 * size, 2 * size}, size, rng);
        }
}

TEST_CASE("the bilinear box bound takes boxes a rounding past the domain's end") {
    // abc_0_13's pole fans: a box starting a rounding past u_max clamps to
    // no width, which the bound refuses (infinite) instead of failing.
    const BSplineSurface s = cylinder();
    const TriangleBound bound(s);
    const double hi = s.u_max(), v0 = s.v_min(), v1 = s.v_max();
    const auto corners = [&](double u0, double u1) {
        const double a = std::min(u0, hi), b = std::min(u1, hi);
        return std::array<Vec3, 4>{evaluate(s, a, v0).point, evaluate(s, b, v0).point,
                                   evaluate(s, b, v1).point, evaluate(s, a, v1).point};
    };
    const double past = std::nextafter(hi, 2 * hi + 1);
    const double beyond = std::nextafter(past, 2 * hi + 1);
    CHECK(std::isinf(bound.bilinear_box({past, beyond, v0, v1}, corners(past, beyond))));
    const double inside = hi - 0.25 * (hi - s.u_min());
    const double b = bound.bilinear_box({inside, past, v0, v1}, corners(inside, past));
    CHECK(b >= 0);
    CHECK(std::isfinite(b));
}
