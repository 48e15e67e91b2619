// SPDX-License-Identifier: MIT
// evaluate() and enclose_homogeneous() of a bicubic, biquadratic or bilinear
// patch run the fixed-degree paths (fixed_degree.h): the same values as the
// generic loops, bit for bit.
#include <seamless/spline/bezier_patch.h>
#include <seamless/spline/fixed_degree.h>

#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

using namespace seamless;

namespace {

BezierPatch random_patch(std::mt19937& rng, bool rational, int degree = 3) {
    std::uniform_real_distribution<double> P(-3.0, 3.0), W(0.2, 5.0);
    BezierPatch b;
    b.p = b.q = degree;
    b.rational = rational;
    for (int i = 0; i <= degree; ++i)
        for (int j = 0; j <= degree; ++j)
            b.at(i, j) = HPoint::from({P(rng), P(rng), P(rng)}, rational ? W(rng) : 1.0);
    return b;
}

} // namespace

TEST_CASE("evaluate() of a bicubic, biquadratic or bilinear patch gives the generic sums' point, "
          "bit for bit",
          "[spline][fixed_degree]") {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    for (int n = 0; n < 600; ++n) {
        const BezierPatch b = random_patch(rng, n % 2 == 1, 3 - n / 200);
        for (int k = 0; k < 20; ++k) {
            const double s = k == 0 ? 0.0 : k == 1 ? 1.0 : U(rng), t = k == 0 ? 1.0 : U(rng);
            // evaluate_homogeneous runs the generic loops of any degree.
            const HPoint X = evaluate_homogeneous(b, s, t);
            const Vec3 p = X.xyz() / X.w;
            const SurfacePoint sp = evaluate(b, s, t);
            CHECK(sp.point.x == p.x);
            CHECK(sp.point.y == p.y);
            CHECK(sp.point.z == p.z);
            // The polynomial path (no quotient) is within rounding of it.
            if (!b.rational && b.p == 3) {
                const SurfacePoint q = evaluate_fixed<3, 3, false>(b, s, t);
                CHECK(norm(q.point - sp.point) <= 1e-13);
                CHECK(norm(q.du - sp.du) <= 1e-12);
                CHECK(norm(q.dv - sp.dv) <= 1e-12);
            }
        }
    }
}

TEST_CASE("enclose_homogeneous() of a bicubic, biquadratic or bilinear patch gives the generic "
          "loops' enclosures, bit for bit",
          "[spline][fixed_degree][heavy]") {
    std::mt19937 rng(12);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    const double special[] = {0.0, -0.0, 1e-310, -1e300, 1e308, std::nan("")};
    for (int n = 0; n < 600; ++n) {
        const int degree = 3 - n / 200;
        BezierPatch b = random_patch(rng, n % 2 == 1, degree);
        // Some patches with signed zeros, subnormals, huge values (overflow) and NaN.
        if (n % 10 == 9)
            b.at(n % (degree + 1), (n / 4) % (degree + 1))[n % 4] = special[(n / 10) % 6];
        for (int k = 0; k < 20; ++k) {
            const double s = k == 0 ? 0.0 : k == 1 ? 1.0 : U(rng), t = k == 0 ? 1.0 : U(rng);
            for (int dims = 3; dims <= 4; ++dims) {
                Interval fast[4], generic[4];
                enclose_homogeneous(b, s, t, dims, fast);
                enclose_homogeneous_any_degree(b, s, t, dims, generic);
                for (int c = 0; c < dims; ++c) {
                    CHECK(std::bit_cast<std::uint64_t>(fast[c].lo()) ==
                          std::bit_cast<std::uint64_t>(generic[c].lo()));
                    CHECK(std::bit_cast<std::uint64_t>(fast[c].hi()) ==
                          std::bit_cast<std::uint64_t>(generic[c].hi()));
                }
            }
        }
    }
}

TEST_CASE("ray_system_fixed (bicubic, biquadratic, bilinear) gives G = (X - a Z, Y - b Z) and its "
          "partials within rounding",
          "[spline][fixed_degree]") {
    std::mt19937 rng(13);
    std::uniform_real_distribution<double> U(0.0, 1.0), E(-2.0, 2.0);
    for (int n = 0; n < 300; ++n) {
        const bool rational = n % 2 == 1;
        const int degree = 3 - n / 100;
        const BezierPatch b = random_patch(rng, rational, degree);
        for (int k = 0; k < 20; ++k) {
            const double s = k == 0 ? 0.0 : U(rng), t = k == 0 ? 1.0 : U(rng);
            const double a = E(rng), bb = E(rng);
            RaySystemAt g{};
            if (degree == 3) g = ray_system_fixed<3, 3>(b, a, bb, s, t);
            if (degree == 2) g = ray_system_fixed<2, 2>(b, a, bb, s, t);
            if (degree == 1) g = ray_system_fixed<1, 1>(b, a, bb, s, t);
            const double *G = g.G, *Gs = g.Gs, *Gt = g.Gt;
            const HPoint X = evaluate_homogeneous(b, s, t);
            CHECK(std::abs(G[0] - (X.x - a * X.z)) <= 1e-12 * (1 + X.w));
            CHECK(std::abs(G[1] - (X.y - bb * X.z)) <= 1e-12 * (1 + X.w));
            if (rational) continue;
            // Polynomial: W = 1, so the partials are those of the point.
            const SurfacePoint sp = evaluate(b, s, t);
            CHECK(std::abs(Gs[0] - (sp.du.x - a * sp.du.z)) <= 1e-11);
            CHECK(std::abs(Gs[1] - (sp.du.y - bb * sp.du.z)) <= 1e-11);
            CHECK(std::abs(Gt[0] - (sp.dv.x - a * sp.dv.z)) <= 1e-11);
            CHECK(std::abs(Gt[1] - (sp.dv.y - bb * sp.dv.z)) <= 1e-11);
        }
    }
}

TEST_CASE("enclose_homogeneous() with the frame: the same enclosures, and evaluate()'s point and "
          "derivatives up to rounding",
          "[spline][fixed_degree][heavy]") {
    // Bicubic, biquadratic, bilinear (de Casteljau's levels), and degree
    // (3, 2) patches (evaluate()'s frame), rational or not; the corners and
    // random points.
    std::mt19937 rng(13);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    std::vector<BezierPatch> patches;
    for (int degree : {3, 2, 1, 3})
        for (int n = 0; n < 200; ++n) {
            patches.push_back(random_patch(rng, n % 2 == 1, degree));
            if (patches.size() > 600) patches.back().q = 2;
        }
    for (const BezierPatch& b : patches)
        for (int k = 0; k < 20; ++k) {
            const double s = k < 4 ? k % 2 : U(rng), t = k < 4 ? k / 2 : U(rng);
            for (int dims = 3; dims <= 4; ++dims) {
                Interval plain[4], with[4];
                SurfacePoint frame;
                enclose_homogeneous(b, s, t, dims, plain);
                enclose_homogeneous(b, s, t, dims, with, frame);
                for (int c = 0; c < dims; ++c) {
                    CHECK(std::bit_cast<std::uint64_t>(with[c].lo()) ==
                          std::bit_cast<std::uint64_t>(plain[c].lo()));
                    CHECK(std::bit_cast<std::uint64_t>(with[c].hi()) ==
                          std::bit_cast<std::uint64_t>(plain[c].hi()));
                }
                const SurfacePoint sp = evaluate(b, s, t);
                const double scale = 1 + norm(sp.point) + norm(sp.du) + norm(sp.dv);
                CHECK(norm(frame.point - sp.point) <= 1e-12 * scale);
                CHECK(norm(frame.du - sp.du) <= 1e-11 * scale);
                CHECK(norm(frame.dv - sp.dv) <= 1e-11 * scale);
            }
        }
}

TEST_CASE("evaluate_point() of patches up to bicubic, mixed degrees too, gives the generic sums' "
          "point, bit for bit",
          "[spline][fixed_degree]") {
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> U(0.0, 1.0), P(-3.0, 3.0), W(0.2, 5.0);
    for (int p = 1; p <= 4; ++p)
        for (int q = 1; q <= 4; ++q)
            for (bool rational : {false, true}) {
                BezierPatch b;
                b.p = p, b.q = q, b.rational = rational;
                for (int i = 0; i <= p; ++i)
                    for (int j = 0; j <= q; ++j)
                        b.at(i, j) =
                            HPoint::from({P(rng), P(rng), P(rng)}, rational ? W(rng) : 1.0);
                for (int k = 0; k < 50; ++k) {
                    const double s = U(rng), t = U(rng);
                    const HPoint X = evaluate_homogeneous(b, s, t);
                    const Vec3 want = rational ? X.xyz() / X.w : X.xyz();
                    const Vec3 got = evaluate_point(b, s, t);
                    INFO("degrees " << p << "," << q << " rational " << rational);
                    CHECK(got.x == want.x);
                    CHECK(got.y == want.y);
                    CHECK(got.z == want.z);
                }
            }
}
