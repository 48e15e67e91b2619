// SPDX-License-Identifier: MIT
#include <seamless/spline/enclosure/triangle_restriction.h>
#include <spline/patch_samples.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

using namespace seamless;
using namespace seamless::test;

namespace {

// The triangular Bezier patch at barycentric lambda (de Casteljau on the
// triangle, in long double).
std::array<long double, 4> triangular_at(const TriangularNet& net, const double* lambda) {
    const int n = net.n;
    std::vector<std::array<long double, 4>> c(TriangularNet::index(n, n, 0) + 1);
    for (int i = 0; i <= n; ++i)
        for (int j = 0; i + j <= n; ++j)
            for (int k = 0; k < 4; ++k) c[TriangularNet::index(n, i, j)][k] = net.at(i, j)[k];
    for (int d = n; d > 0; --d)
        for (int i = 0; i < d; ++i)
            for (int j = 0; i + j < d; ++j)
                for (int k = 0; k < 4; ++k)
                    c[TriangularNet::index(d - 1, i, j)][k] =
                        lambda[0] * c[TriangularNet::index(d, i + 1, j)][k] +
                        lambda[1] * c[TriangularNet::index(d, i, j + 1)][k] +
                        lambda[2] * c[TriangularNet::index(d, i, j)][k];
    return c[0];
}

// The patch's homogeneous point at (s, t) by the tensor-product Bernstein
// sums in long double (also outside [0,1]^2).
std::array<long double, 4> tensor_at(const BezierPatch& b, long double s, long double t) {
    auto bern = [](int n, long double x, long double* B) {
        for (int i = 0; i <= n; ++i) {
            long double c = 1;
            for (int k = 1; k <= i; ++k) c = c * (n - i + k) / k;
            B[i] = c * std::pow(x, i) * std::pow(1 - x, n - i);
        }
    };
    long double Bu[BezierPatch::kMaxOrder], Bv[BezierPatch::kMaxOrder];
    bern(b.p, s, Bu);
    bern(b.q, t, Bv);
    std::array<long double, 4> out{0, 0, 0, 0};
    for (int i = 0; i <= b.p; ++i)
        for (int j = 0; j <= b.q; ++j)
            for (int k = 0; k < 4; ++k) out[k] += Bu[i] * Bv[j] * b.at(i, j)[k];
    return out;
}

} // namespace

TEST_CASE("a patch restricted to a triangle is the triangular Bezier patch of its blossom",
          "[heavy]") {
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> in(0, 1), out(-0.2, 1.2), b(0, 1);
    for (auto [p, q] : {std::pair{1, 1}, {2, 1}, {2, 2}, {3, 3}, {1, 3}, {5, 2}, {9, 9}, {2, 9}})
        for (bool rational : {false, true})
            for (int round = 0; round < 20; ++round) {
                const BezierPatch patch = random_patch(rng, p, q, rational);
                std::array<std::array<double, 2>, 3> st;
                // Inside the square and, every other round, partly outside it;
                // some rounds with corners sharing a parameter value (the
                // restriction orders the corners along each parameter).
                for (auto& x : st)
                    x = round % 2 ? std::array{out(rng), out(rng)} : std::array{in(rng), in(rng)};
                if (round % 5 == 2) st[1][0] = st[0][0];
                if (round % 5 == 4) st[2][1] = st[1][1] = st[0][1];
                TriangularNet net;
                restrict_to_triangle(patch, st, net);
                REQUIRE(net.n == p + q);
                // The corner coefficients are the patch at the corners, and
                // every point of the triangle agrees.
                for (int m = 0; m < 30; ++m) {
                    double l1 = b(rng), l2 = b(rng);
                    if (m < 3) l1 = m == 1, l2 = m == 2;
                    if (l1 + l2 > 1) l1 = 1 - l1, l2 = 1 - l2;
                    const double lambda[3] = {1 - l1 - l2, l1, l2};
                    const long double s = lambda[0] * (long double)st[0][0] +
                                          lambda[1] * (long double)st[1][0] +
                                          lambda[2] * (long double)st[2][0];
                    const long double t = lambda[0] * (long double)st[0][1] +
                                          lambda[1] * (long double)st[1][1] +
                                          lambda[2] * (long double)st[2][1];
                    const auto a = triangular_at(net, lambda), e = tensor_at(patch, s, t);
                    for (int k = 0; k < 4; ++k) {
                        INFO("degree " << p << "," << q << " coordinate " << k);
                        // The net's error, and the long double sums' own
                        // rounding (lambda rounded to double).
                        CHECK(std::abs(double(a[k] - e[k])) <= net.error + 1e-15);
                    }
                }
            }
}

TEST_CASE("the restriction's error bound holds against long double de Casteljau") {
    // Coefficients far from 1 in magnitude: the bound scales with them.
    std::mt19937_64 rng(23);
    BezierPatch patch = random_patch(rng, 3, 3, true);
    for (auto& c : patch.cp) c = 1e6 * c;
    const std::array<std::array<double, 2>, 3> st{{{0.1, 0.2}, {0.7, 0.3}, {0.4, 0.9}}};
    TriangularNet net;
    restrict_to_triangle(patch, st, net);
    CHECK(net.error > 0);
    CHECK(net.error < 1e-6);
    const double lambda[3] = {1, 0, 0};
    const auto a = triangular_at(net, lambda), e = tensor_at(patch, 0.1L, 0.2L);
    for (int k = 0; k < 4; ++k) CHECK(std::abs(double(a[k] - e[k])) <= net.error);
}

TEST_CASE("the box stage of the restriction is the patch over the corners' bounding box") {
    std::mt19937_64 rng(41);
    std::uniform_real_distribution<double> out(-0.2, 1.2), b(0, 1);
    for (auto [p, q] : {std::pair{1, 1}, {3, 2}, {9, 9}})
        for (int round = 0; round < 10; ++round) {
            const BezierPatch patch = random_patch(rng, p, q, round % 2 == 1);
            std::array<std::array<double, 2>, 3> st;
            for (auto& x : st) x = {out(rng), out(rng)};
            BoxNet box;
            restrict_to_box(patch, st, box);
            CHECK(box.s_lo == std::min({st[0][0], st[1][0], st[2][0]}));
            CHECK(box.t_hi == std::max({st[0][1], st[1][1], st[2][1]}));
            BezierPatch over = patch;
            for (int i = 0; i <= p; ++i)
                for (int j = 0; j <= q; ++j) over.at(i, j) = box.at(i, j);
            for (int m = 0; m < 10; ++m) {
                const double x = b(rng), y = b(rng);
                const auto a = tensor_at(over, x, y);
                const auto e = tensor_at(patch, box.s_lo + x * (box.s_hi - box.s_lo),
                                         box.t_lo + y * (box.t_hi - box.t_lo));
                for (int k = 0; k < 4; ++k)
                    CHECK(std::abs(double(a[k] - e[k])) <= box.error + 1e-15);
            }
        }
}
