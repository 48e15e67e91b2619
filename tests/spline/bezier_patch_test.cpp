// SPDX-License-Identifier: MIT
// split(): de Casteljau along u or v; the v split is the u split of the
// transposed patch, bit for bit, and the halves are the original patch.
#include "spline/patch_samples.h"

#include <seamless/spline/bezier_patch.h>

#include <catch2/catch.hpp>

#include <bit>
#include <cmath>

using namespace seamless;

namespace {

// b with s and t exchanged: (i, j) -> (j, i), degrees and ranges swapped.
BezierPatch transposed(const BezierPatch& b) {
    BezierPatch t = b;
    t.p = b.q;
    t.q = b.p;
    t.u0 = b.v0, t.u1 = b.v1, t.v0 = b.u0, t.v1 = b.u1;
    for (int i = 0; i <= b.p; ++i)
        for (int j = 0; j <= b.q; ++j) t.at(j, i) = b.at(i, j);
    return t;
}

bool same_bits(double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

bool same_patch(const BezierPatch& a, const BezierPatch& b) {
    if (a.p != b.p || a.q != b.q || a.rational != b.rational || a.surface != b.surface)
        return false;
    if (!same_bits(a.u0, b.u0) || !same_bits(a.u1, b.u1) || !same_bits(a.v0, b.v0) ||
        !same_bits(a.v1, b.v1))
        return false;
    for (int i = 0; i <= a.p; ++i)
        for (int j = 0; j <= a.q; ++j)
            for (int c = 0; c < 4; ++c)
                if (!same_bits(a.at(i, j)[c], b.at(i, j)[c])) return false;
    return true;
}

} // namespace

TEST_CASE("split along v is split along u of the transposed patch, bit for bit",
          "[spline][bezier_patch]") {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> X(0.05, 0.95);
    for (int n = 0; n < 200; ++n) {
        BezierPatch b = test::random_patch(rng, 1 + n % 4, 1 + (n / 4) % 3, n % 2 == 1);
        b.surface = n;
        b.u0 = -1.5, b.u1 = 2.25, b.v0 = 0.5, b.v1 = 0.75;
        const double x = X(rng);
        BezierPatch lo, hi, tlo, thi;
        split(b, Direction::v, x, lo, hi);
        split(transposed(b), Direction::u, x, tlo, thi);
        CHECK(same_patch(lo, transposed(tlo)));
        CHECK(same_patch(hi, transposed(thi)));
        BezierPatch ulo, uhi;
        split_u(b, x, ulo, uhi);
        split(b, Direction::u, x, lo, hi);
        CHECK(same_patch(lo, ulo));
        CHECK(same_patch(hi, uhi));
    }
}

TEST_CASE("the halves of a split are the patch and keep their parameter rectangles",
          "[spline][bezier_patch]") {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> X(0.0, 1.0);
    for (int n = 0; n < 100; ++n) {
        BezierPatch b = test::random_patch(rng, 3, 2, n % 2 == 1);
        b.u0 = 1, b.u1 = 3, b.v0 = -1, b.v1 = 0;
        const double x = 0.25;
        for (Direction d : {Direction::u, Direction::v}) {
            BezierPatch lo, hi;
            split(b, d, x, lo, hi);
            const bool u = d == Direction::u;
            CHECK(lo.u0 == 1);
            CHECK(lo.u1 == (u ? 1.5 : 3.0));
            CHECK(hi.u0 == (u ? 1.5 : 1.0));
            CHECK(lo.v1 == (u ? 0.0 : -0.75));
            CHECK(hi.v0 == (u ? -1.0 : -0.75));
            for (int k = 0; k < 10; ++k) {
                const double s = X(rng), t = X(rng);
                const Vec3 a = evaluate(lo, s, t).point;
                const Vec3 e = u ? evaluate(b, x * s, t).point : evaluate(b, s, x * t).point;
                const Vec3 f = evaluate(hi, s, t).point;
                const Vec3 g = u ? evaluate(b, x + (1 - x) * s, t).point
                                 : evaluate(b, s, x + (1 - x) * t).point;
                CHECK(norm(a - e) <= 1e-12 * (1 + norm(e)));
                CHECK(norm(f - g) <= 1e-12 * (1 + norm(g)));
            }
        }
    }
}
