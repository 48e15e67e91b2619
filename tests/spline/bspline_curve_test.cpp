// SPDX-License-Identifier: MIT
// B-spline curve evaluation: the point alone (evaluate_point) is the point
// of the full evaluation to the bit, so that the edges' samples and their
// mesh vertices agree; and a curve reproduces its control polygon's line
// where that is straight (linear precision).
#include <seamless/spline/bspline_curve.h>

#include <catch2/catch.hpp>

#include <random>

using namespace seamless;

TEST_CASE("curve evaluate_point: evaluate's point to the bit", "[spline]") {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> x(-10, 10), w(0.1, 8);
    for (int degree = 1; degree <= kMaxDegree; ++degree)
        for (bool rational : {false, true}) {
            BSplineCurve c;
            c.degree = degree;
            const int n = degree + 5;
            for (int i = 0; i < n + degree + 1; ++i) c.knots.push_back(i < 3 ? 0.0 : i * 0.7);
            for (int i = 0; i < n; ++i) {
                c.points.push_back({x(rng), x(rng), 0});
                if (rational) c.weights.push_back(w(rng));
            }
            std::uniform_real_distribution<double> t(c.t_min() - 1, c.t_max() + 1);
            for (int k = 0; k < 200; ++k) {
                const double at = t(rng);
                const Vec3 a = evaluate_point(c, at), b = evaluate(c, at).point;
                INFO("degree " << degree << " rational " << rational << " t " << at);
                REQUIRE((a.x == b.x && a.y == b.y && a.z == b.z));
            }
        }
}

TEST_CASE("curve evaluation: a straight control polygon gives its line", "[spline]") {
    BSplineCurve c;
    c.degree = 3;
    c.knots = {0, 0, 0, 0, 1, 2, 2, 2, 2};
    for (int i = 0; i < 5; ++i) c.points.push_back({1.0 + i, 2.0 * i, -1.0});
    for (double t = 0; t <= 2; t += 0.125) {
        const Vec3 p = evaluate_point(c, t);
        CHECK(p.y == Approx(2 * (p.x - 1)).margin(1e-12));
        CHECK(p.z == -1.0);
    }
}
