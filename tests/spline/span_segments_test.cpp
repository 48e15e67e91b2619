// SPDX-License-Identifier: MIT
// Span segments (span_segments.h): the Bezier segment of each knot span,
// computed by blossoming on first use, evaluates to the B-spline curve's
// point and tangent up to rounding, at every degree, rational, with repeated and
// unclamped knots.
#include <seamless/spline/span_segments.h>

#include <catch2/catch.hpp>

#include <random>

using namespace seamless;

TEST_CASE("span segments: the curve's points and tangents up to rounding", "[spline]") {
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> x(-5, 5), w(0.2, 5);
    for (int p = 1; p <= kMaxDegree; ++p)
        for (bool rational : {false, true}) {
            BSplineCurve c;
            c.degree = p;
            const int n = p + 6;
            // Unclamped, one interior knot doubled.
            for (int i = 0; i < n + p + 1; ++i)
                c.knots.push_back(i == p + 3 ? 0.3 * (i - 1) * (i - 1) : 0.3 * i * i);
            for (int i = 0; i < n; ++i) {
                c.points.push_back({x(rng), x(rng), x(rng)});
                if (rational) c.weights.push_back(w(rng));
            }
            SpanSegments spans(c);
            std::uniform_real_distribution<double> t(c.t_min() - 0.5, c.t_max() + 0.5);
            for (int k = 0; k < 300; ++k) {
                const double at = k < static_cast<int>(c.knots.size()) ? c.knots[k] : t(rng);
                INFO("degree " << p << " rational " << rational << " t " << at);
                REQUIRE(distance(spans.point(at), evaluate_point(c, at)) <=
                        1e-11 * (1 + norm(evaluate_point(c, at))));
                // At a knot the span's segment is find_span's, as evaluate's.
                const Vec3 d = evaluate(c, at).tangent;
                REQUIRE(distance(spans.tangent(at), d) <= 1e-9 * (1 + norm(d)));
            }
        }
}
