// SPDX-License-Identifier: MIT
#include <seamless/tessellate/power_basis.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace seamless {
namespace {

// Power coefficient i of the cubic Bernstein basis function k: sum_k M[i][k] P_k.
constexpr double kM[4][4] = {{1, 0, 0, 0}, {-3, 3, 0, 0}, {3, -6, 3, 0}, {-1, 3, -3, 1}};
// Column sums of |M|: how much of |P_k| can reach the coefficients.
constexpr double kColumn[4] = {8, 12, 6, 1};

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
    assert(has_power_basis(b));
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
        double T[4][4]; // T[i][l] = sum_k M[i][k] P[k][l]
        for (int i = 0; i < 4; ++i)
            for (int l = 0; l < 4; ++l) {
                double sum = 0;
                for (int k = 0; k <= i; ++k) sum += kM[i][k] * P[k][l];
                T[i][l] = sum;
            }
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) {
                double sum = 0;
                for (int l = 0; l <= j; ++l) sum += T[i][l] * kM[j][l];
                pb.a[c][j][i] = sum;
            }
        for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 4; ++i) pb.at[c][j][i] = (j + 1) * pb.a[c][j + 1][i];
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

namespace {

// Two lanes at a time (SSE2; GCC/Clang vector extension): the rows i = 0, 1
// and i = 2, 3 of the power basis. Each lane does the operations of the
// scalar form in its order, so the values (and the rounding bound) are those
// of the scalar Horner passes.
using Lanes = double __attribute__((vector_size(16)));

Lanes load(const double* p) {
    return *static_cast<const Lanes*>(__builtin_assume_aligned(p, 16));
}

// Rows (0, 1) and (2, 3) of coordinate c at t: sum_j a_ij t^j by Horner.
void rows(const PowerBasisPatch& pb, int c, Lanes T, Lanes row[2]) {
    const double(&a)[4][4] = pb.a[c];
    for (int h = 0; h < 2; ++h)
        row[h] = ((load(a[3] + 2 * h) * T + load(a[2] + 2 * h)) * T + load(a[1] + 2 * h)) * T +
                 load(a[0] + 2 * h);
}

} // namespace

SurfacePoint evaluate(const PowerBasisPatch& pb, double s, double t) {
    const Lanes T = {t, t}, S = {s, s};
    double X[3], Xu[3], Xv[3];
    for (int c = 0; c < 3; ++c) {
        const double(&d)[3][4] = pb.at[c];
        Lanes row[2], rowv[2];
        rows(pb, c, T, row);
        for (int h = 0; h < 2; ++h)
            rowv[h] = (load(d[2] + 2 * h) * T + load(d[1] + 2 * h)) * T + load(d[0] + 2 * h);
        // (row_i, rowv_i): the point's and the t-derivative's Horner passes in s together.
        const Lanes r0 = __builtin_shufflevector(row[0], rowv[0], 0, 2);
        const Lanes r1 = __builtin_shufflevector(row[0], rowv[0], 1, 3);
        const Lanes r2 = __builtin_shufflevector(row[1], rowv[1], 0, 2);
        const Lanes r3 = __builtin_shufflevector(row[1], rowv[1], 1, 3);
        const Lanes xv = ((r3 * S + r2) * S + r1) * S + r0;
        X[c] = xv[0];
        Xv[c] = xv[1];
        Xu[c] = ((3 * r3[0]) * s + 2 * r2[0]) * s + r1[0];
    }
    return {pb.origin + Vec3{X[0], X[1], X[2]}, {Xu[0], Xu[1], Xu[2]}, {Xv[0], Xv[1], Xv[2]}};
}

Vec3 evaluate_point(const PowerBasisPatch& pb, double s, double t) {
    const Lanes T = {t, t};
    double X[3];
    for (int c = 0; c < 3; ++c) {
        Lanes row[2];
        rows(pb, c, T, row);
        X[c] = ((row[1][1] * s + row[1][0]) * s + row[0][1]) * s + row[0][0];
    }
    return pb.origin + Vec3{X[0], X[1], X[2]};
}

} // namespace seamless
