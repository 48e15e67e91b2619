// SPDX-License-Identifier: MIT
#include <seamless/interval/hansen_sengupta.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace seamless;

namespace {

// F(x, y) = (x^2 + y^2 - 1, x - y): zeros at +-(1/sqrt2, 1/sqrt2).
IVec<2> F(const IVec<2>& v) {
    return IVec<2>{{sqr(v[0]) + sqr(v[1]) - Interval(1.0), v[0] - v[1]}};
}
IMat<2> J(const IVec<2>& v) {
    IMat<2> A;
    A(0, 0) = Interval(2.0) * v[0];
    A(0, 1) = Interval(2.0) * v[1];
    A(1, 0) = 1.0;
    A(1, 1) = -1.0;
    return A;
}
HansenSenguptaStep<2> step(const IVec<2>& x) {
    RVec<2> c = mid(x);
    return hansen_sengupta(J(x), F(to_ivec<2>(c)), x, c);
}

} // namespace

TEST_CASE("midpoint inverse", "[hansen_sengupta]") {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int n = 0; n < 1000; ++n) {
        RMat<3> A, C;
        for (double& a : A) a = u(rng);
        REQUIRE(invert<3>(A, C));
        for (int i = 0; i < 3; ++i)
            for (int k = 0; k < 3; ++k) {
                double s = 0;
                for (int j = 0; j < 3; ++j) s += A[i * 3 + j] * C[j * 3 + k];
                // Random matrices are well enough conditioned for this nearly always;
                // a residual bound relative to the condition would be overkill here.
                CHECK(std::abs(s - (i == k ? 1.0 : 0.0)) < 1e-6);
            }
    }
    RMat<2> S{1, 2, 2, 4}, C;
    CHECK(!invert<2>(S, C));
    RMat<2> Z{0, 0, 0, 0};
    CHECK(!invert<2>(Z, C));
    RMat<2> N{1, NAN, 0, 1};
    CHECK(!invert<2>(N, C));
}

TEST_CASE("a box holding one zero strictly inside is certified (Theorem 6 iii)",
          "[hansen_sengupta]") {
    const double r = std::sqrt(0.5);
    IVec<2> x{{Interval(r - 0.1, r + 0.05), Interval(r - 0.07, r + 0.1)}};
    bool unique = false;
    for (int i = 0; i < 20 && !unique; ++i) {
        auto s = step(x);
        REQUIRE(!s.box.is_empty());
        REQUIRE(contains(x, s.box));
        REQUIRE(s.box[0].contains(r));
        REQUIRE(s.box[1].contains(r));
        unique = s.unique;
        x = s.box;
    }
    CHECK(unique);
    // It keeps contracting to a narrow box (quadratic convergence).
    for (int i = 0; i < 10; ++i) x = step(x).box;
    CHECK(max_width(x) < 1e-14);
    CHECK(x[0].contains(r));
}

TEST_CASE("a box without zero becomes empty (Theorem 6 ii)", "[hansen_sengupta]") {
    IVec<2> x{{Interval(0.1, 0.3), Interval(0.1, 0.3)}};
    bool empty = false;
    for (int i = 0; i < 10 && !empty; ++i) {
        auto s = step(x);
        empty = s.box.is_empty();
        CHECK(!s.unique);
        x = s.box;
    }
    CHECK(empty);
}

TEST_CASE("a box with two zeros is never certified and keeps both", "[hansen_sengupta]") {
    const double r = std::sqrt(0.5);
    IVec<2> x{{Interval(-1, 1), Interval(-1, 1)}};
    for (int i = 0; i < 5; ++i) {
        auto s = step(x);
        CHECK(!s.unique);
        REQUIRE(s.box[0].contains(r));
        REQUIRE(s.box[0].contains(-r));
        x = s.box;
    }
}

TEST_CASE("every zero survives random boxes", "[hansen_sengupta]") {
    const double r = std::sqrt(0.5);
    std::mt19937_64 rng(12);
    std::uniform_real_distribution<double> u(0, 0.6);
    for (int n = 0; n < 2000; ++n) {
        IVec<2> x{{Interval(r - u(rng), r + u(rng)), Interval(r - u(rng), r + u(rng))}};
        auto s = step(x);
        REQUIRE(!s.box.is_empty());
        REQUIRE(s.box[0].contains(r));
        REQUIRE(s.box[1].contains(r));
        // Certified boxes hold exactly this zero (the other one is at -r).
        if (s.unique) REQUIRE(!(x[0].contains(-r) && x[1].contains(-r)));
    }
}

TEST_CASE("singular midpoint falls back to C = I", "[hansen_sengupta]") {
    IMat<2> A; // all zero: no preconditioner
    IVec<2> f{{Interval(0.0), Interval(0.0)}};
    IVec<2> x{{Interval(0, 1), Interval(0, 1)}};
    auto s = hansen_sengupta(A, f, x, mid(x));
    CHECK(!s.preconditioned);
    CHECK(contains(s.box, x)); // nothing learned, nothing lost
    CHECK(!s.unique);
}
