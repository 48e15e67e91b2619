// SPDX-License-Identifier: MIT
#include <seamless/interval/gauss_seidel.h>

#include <catch2/catch.hpp>

#include <random>

using namespace seamless;

namespace {

template <int N> IVec<N> random_box(std::mt19937_64& rng, double w) {
    std::uniform_real_distribution<double> u(-2, 2), r(0, w);
    IVec<N> x;
    for (int i = 0; i < N; ++i) {
        double c = u(rng);
        x[i] = {c - r(rng), c + r(rng)};
    }
    return x;
}

// For random A~ in A and y~ in x, b~ = A~ y~ lies in b = A x; Gamma(A, b, x)
// must keep y~ (it encloses every solution in x of every A~ y = b~).
template <int N> void check_keeps_solutions(std::mt19937_64& rng, double spread) {
    std::uniform_real_distribution<double> u(-1, 1), s(0, 1);
    IMat<N> A;
    RMat<N> At;
    for (int i = 0; i < N; ++i)
        for (int k = 0; k < N; ++k) {
            double c = (i == k ? 3.0 : 0.0) + u(rng);
            double r = spread * s(rng);
            A(i, k) = {c - r, c + r};
            At[i * N + k] = c + r * u(rng);
        }
    IVec<N> x = random_box<N>(rng, 0.5);
    RVec<N> y;
    for (int i = 0; i < N; ++i) y[i] = x[i].lo() + s(rng) * (x[i].hi() - x[i].lo());
    IVec<N> b;
    for (int i = 0; i < N; ++i) {
        Interval bi(0.0);
        for (int k = 0; k < N; ++k) bi += Interval(At[i * N + k]) * Interval(y[k]);
        b[i] = bi;
    }
    IVec<N> g = gauss_seidel(A, b, x);
    REQUIRE(contains(x, g));
    REQUIRE(contains(g, y));
}

} // namespace

TEST_CASE("Gauss-Seidel keeps every solution in the box", "[gauss_seidel]") {
    std::mt19937_64 rng(7);
    for (int i = 0; i < 5000; ++i) {
        check_keeps_solutions<2>(rng, 0.1);
        check_keeps_solutions<3>(rng, 0.1);
        check_keeps_solutions<2>(rng, 4.0); // diagonal may contain 0: extended division
        check_keeps_solutions<3>(rng, 4.0);
    }
}

TEST_CASE("Gauss-Seidel on a thin diagonal system solves it", "[gauss_seidel]") {
    IMat<2> A;
    A(0, 0) = 2;
    A(1, 1) = 4;
    IVec<2> b{{Interval(1.0), Interval(1.0)}};
    IVec<2> x{{Interval(-10, 10), Interval(-10, 10)}};
    IVec<2> g = gauss_seidel(A, b, x);
    CHECK(g[0].contains(0.5)); // outward rounded: a few ulps around the solution
    CHECK(g[0].width() < 1e-15);
    CHECK(g[1].contains(0.25));
    CHECK(g[1].width() < 1e-15);
}

TEST_CASE("Gauss-Seidel uses updated components (not Jacobi)", "[gauss_seidel]") {
    // Lower triangular: y0 = 1, then y1 = (2 - y0) / 1 = 1 exactly when y0 is updated;
    // a Jacobi step would use x0 = [-10, 10] and give a wide y1.
    IMat<2> A;
    A(0, 0) = 1;
    A(1, 0) = 1;
    A(1, 1) = 1;
    IVec<2> b{{Interval(1.0), Interval(2.0)}};
    IVec<2> x{{Interval(-10, 10), Interval(-10, 10)}};
    IVec<2> g = gauss_seidel(A, b, x);
    CHECK(g[1].width() < 1e-12);
    CHECK(g[1].contains(1.0));
}

TEST_CASE("Gauss-Seidel returns empty when no solution is in the box", "[gauss_seidel]") {
    IMat<2> A;
    A(0, 0) = 1;
    A(1, 1) = 1;
    IVec<2> b{{Interval(5.0), Interval(0.0)}};
    IVec<2> x{{Interval(-1, 1), Interval(-1, 1)}};
    CHECK(gauss_seidel(A, b, x).is_empty());
    // 0 in the diagonal, numerator away from 0: the gap excludes the box.
    A(0, 0) = Interval(-1, 1);
    b[0] = Interval(1, 2);
    x[0] = Interval(-0.5, 0.5);
    CHECK(gauss_seidel(A, b, x).is_empty());
}
