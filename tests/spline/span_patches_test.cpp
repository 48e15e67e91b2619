// SPDX-License-Identifier: MIT
// Span patches (span_patches.h): the Bezier patch of each knot span,
// extracted on first use, evaluates to the B-spline surface's point and
// derivatives up to rounding, on rational surfaces with repeated and unclamped knots too.
#include <seamless/spline/span_patches.h>

#include <catch2/catch.hpp>

#include <random>

using namespace seamless;

namespace {

BSplineSurface random_surface(std::mt19937& rng, int p, int q, int nu, int nv, bool rational) {
    std::uniform_real_distribution<double> x(-1, 1), w(0.2, 5);
    BSplineSurface s;
    s.degree_u = p, s.degree_v = q, s.size_u = nu, s.size_v = nv;
    // Unclamped, with a knot repeated up to the degree (a crease).
    for (int i = 0; i < nu + p + 1; ++i) s.knots_u.push_back(i == p + 2 ? i - 1 : i);
    for (int j = 0; j < nv + q + 1; ++j) s.knots_v.push_back(0.5 * j * j);
    for (int i = 0; i < nu * nv; ++i) {
        s.points.push_back({x(rng), x(rng), x(rng)});
        if (rational) s.weights.push_back(w(rng));
    }
    return s;
}

} // namespace

TEST_CASE("span patches: the surface's points and derivatives up to rounding", "[spline]") {
    std::mt19937 rng(3);
    // Up to bicubic the Bernstein sums, above Horner's rule on a scaled net.
    for (const auto& [p, q] :
         {std::pair{1, 1}, {2, 1}, {2, 2}, {3, 3}, {5, 2}, {4, 4}, {9, 9}, {kMaxDegree, 1}}) {
        for (bool rational : {false, true}) {
            const BSplineSurface s = random_surface(rng, p, q, p + 4, q + 3, rational);
            SpanPatches spans(s);
            std::uniform_real_distribution<double> u(s.u_min() - 0.1, s.u_max() + 0.1),
                v(s.v_min(), s.v_max());
            for (int k = 0; k < 400; ++k) {
                const double a = u(rng), b = v(rng);
                INFO("degree " << p << "," << q << " rational " << rational << " at " << a << ","
                               << b);
                REQUIRE(distance(spans.point(a, b), evaluate_point(s, a, b)) <= 1e-12);
                const SurfacePoint at = spans.at(a, b), exact = evaluate(s, a, b);
                REQUIRE(distance(at.point, exact.point) <= 1e-12);
                REQUIRE(distance(at.du, exact.du) <= 1e-9 * (1 + norm(exact.du)));
                REQUIRE(distance(at.dv, exact.dv) <= 1e-9 * (1 + norm(exact.dv)));
            }
            // Span ends, where find_span picks the upper span.
            for (double k : s.knots_u)
                if (k >= s.u_min() && k <= s.u_max())
                    REQUIRE(distance(spans.point(k, s.v_min()), evaluate_point(s, k, s.v_min())) <=
                            1e-12);
        }
    }
}
