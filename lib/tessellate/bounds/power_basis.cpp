// SPDX-License-Identifier: MIT
#include <seamless/base/check.h>
#include <seamless/tessellate/bounds/power_basis.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace seamless {
namespace {

// Power coefficient i of the cubic Bernstein basis function k: sum_k M[i][k] P_k.
constexpr double kM[4][4] = {{1, 0, 0, 0}, {-3, 3, 0, 0}, {3, -6, 3, 0}, {-1, 3, -3, 1}};
// Column sums of |M|: how much of |P_k| can reach the coefficients.
constexpr double kColumn[4] = {8, 12, 6, 1};

// Four doubles (GCC/Clang vector extension; two SSE2 halves).
using Row = double __attribute__((vector_size(32)));

// gamma_n with room to spare (u = eps / 2, and n u < 0.01 here).
double gamma(int n) {
    return 1.01 * n * (std::numeric_limits<double>::epsilon() / 2);
}

} // namespace

bool has_power_basis(const BezierPatch& b) {
    if (b.p != 3 || b.q != 3) return false;
    for (int i = 0; i <= 3; ++i)
        for (int j = 0; j <= 3; ++j)
            if (b.at(i, j).w != 1) return false;
    return true;
}

PowerBasisPatch power_basis(const BezierPatch& b, bool rounding_bound) {
    SEAMLESS_DCHECK(has_power_basis(b), "power basis of a patch that is not bicubic polynomial");
    PowerBasisPatch pb;
    const HPoint& o = b.at(0, 0);
    pb.origin = {o.x, o.y, o.z};
    double err2 = 0;
    for (int c = 0; c < 3; ++c) {
        // P - o, this coordinate (the weights are 1: the point is xyz).
        double P[4][4], spread = 0, largest = 0, total = 0; // total: sum |a_ij|
        for (int k = 0; k < 4; ++k)
            for (int l = 0; l < 4; ++l) {
                const HPoint& h = b.at(k, l);
                const double v = (c == 0 ? h.x : c == 1 ? h.y : h.z);
                const double ov = (c == 0 ? o.x : c == 1 ? o.y : o.z);
                P[k][l] = v - ov;
            }
        if (rounding_bound)
            for (int k = 0; k < 4; ++k)
                for (int l = 0; l < 4; ++l) {
                    spread += kColumn[k] * kColumn[l] * std::abs(P[k][l]);
                    largest = std::max(largest, std::abs(P[k][l]));
                }
        // The two products by M four coefficients at a time (each lane the
        // scalar sums' operations in their order).
        Row Pk[4], T[4], Tl[4];
        for (int k = 0; k < 4; ++k) std::memcpy(&Pk[k], P[k], sizeof(Row));
        for (int i = 0; i < 4; ++i) { // T[i][l] = sum_k M[i][k] P[k][l]
            Row sum = {0, 0, 0, 0};
            for (int k = 0; k <= i; ++k) sum = sum + kM[i][k] * Pk[k];
            T[i] = sum;
        }
        for (int l = 0; l < 4; ++l)
            for (int i = 0; i < 4; ++i) Tl[l][i] = T[i][l];
        for (int j = 0; j < 4; ++j) { // a[j][i] = sum_l T[i][l] M[j][l]
            Row sum = {0, 0, 0, 0};
            for (int l = 0; l <= j; ++l) sum = sum + Tl[l] * kM[j][l];
            std::memcpy(pb.a[c][j], &sum, sizeof(Row));
        }
        for (int j = 0; j < 3; ++j) {
            Row row;
            std::memcpy(&row, pb.a[c][j + 1], sizeof(Row));
            row = static_cast<double>(j + 1) * row;
            std::memcpy(pb.at[c][j], &row, sizeof(Row));
        }
        if (!rounding_bound) continue;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) total += std::abs(pb.a[c][j][i]);
        const double ov = std::abs(c == 0 ? o.x : c == 1 ? o.y : o.z);
        // Horner twice (13), the coefficients (9), P - o (a convex combination
        // of the rounded differences), the final + o; the sums above rounded too.
        const double e =
            (gamma(16) * total + gamma(10) * spread + gamma(2) * (largest + ov + total)) * 1.01;
        err2 += e * e;
    }
    pb.error = rounding_bound ? 1.01 * std::sqrt(err2) : 0;
    return pb;
}

} // namespace seamless
