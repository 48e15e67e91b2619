// SPDX-License-Identifier: MIT
// evaluate() (bezier_patch.h) with the degrees known at compile time: the
// same operations in the same order (so the same values), the loops unrolled.
// The error bounds' foot projections and the tessellation's normals, centres
// and vertices evaluate the surface millions of times, nearly always on a
// bicubic patch (docs/results/tessellation.md, profile).
#pragma once

#include <seamless/spline/bezier_patch.h>

#include <cmath>

namespace seamless {

// B_i^N(s) and d/ds B_i^N(s), i = 0..N, as bezier_patch.cpp's bernstein().
// Inlined: a call per polynomial cost a call and the arrays' round trip through memory.
template <int N>
[[gnu::always_inline]] inline void bernstein_fixed(double s, double* B, double* dB) {
    double tmp[N + 1];
    tmp[0] = 1.0;
    const double r = 1.0 - s;
    for (int d = 1; d < N; ++d) {
        double prev = 0.0;
        for (int i = 0; i < d; ++i) {
            const double x = tmp[i];
            tmp[i] = prev + r * x;
            prev = s * x;
        }
        tmp[d] = prev;
    }
    for (int i = 0; i <= N; ++i) {
        const double a = i >= 1 ? tmp[i - 1] : 0.0;
        const double b = i <= N - 1 ? tmp[i] : 0.0;
        B[i] = s * a + r * b;
        dB[i] = N * (a - b);
    }
}

// Rational: in homogeneous coordinates and the quotient rule, as evaluate()
// (for any patch of these degrees, rational or not: evaluate()'s values), two
// lanes at a time (x, y) and (z, w) (SSE2; GCC/Clang vector extension), each
// lane doing the scalar form's operations in its order. Polynomial (every
// weight 1): no weight sums and no quotient (W = 1 up to the rounding of the
// Bernstein sums, which the error bounds' rounding allowance counts).
template <int P, int Q, bool Rational>
SurfacePoint evaluate_fixed(const BezierPatch& b, double s, double t) {
    double Bu[P + 1], dBu[P + 1], Bv[Q + 1], dBv[Q + 1];
    bernstein_fixed<P>(s, Bu, dBu);
    bernstein_fixed<Q>(t, Bv, dBv);
    if constexpr (Rational) {
        using Lanes = double __attribute__((vector_size(16)));
        Lanes X[2] = {}, Xu[2] = {}, Xv[2] = {};
        for (int i = 0; i <= P; ++i) {
            Lanes row[2] = {}, rowv[2] = {};
            for (int j = 0; j <= Q; ++j) {
                const HPoint& h = b.at(i, j);
                const Lanes c[2] = {{h.x, h.y}, {h.z, h.w}};
                for (int k = 0; k < 2; ++k) {
                    row[k] = row[k] + Bv[j] * c[k];
                    rowv[k] = rowv[k] + dBv[j] * c[k];
                }
            }
            for (int k = 0; k < 2; ++k) {
                X[k] = X[k] + Bu[i] * row[k];
                Xu[k] = Xu[k] + dBu[i] * row[k];
                Xv[k] = Xv[k] + Bu[i] * rowv[k];
            }
        }
        // Quotient rule: P = X/W, P_s = (X_s - P W_s) / W.
        SurfacePoint r;
        const double w = X[1][1];
        r.point = Vec3{X[0][0], X[0][1], X[1][0]} / w;
        r.du = (Vec3{Xu[0][0], Xu[0][1], Xu[1][0]} - Xu[1][1] * r.point) / w;
        r.dv = (Vec3{Xv[0][0], Xv[0][1], Xv[1][0]} - Xv[1][1] * r.point) / w;
        return r;
    } else {
        Vec3 X{}, Xu{}, Xv{};
        for (int i = 0; i <= P; ++i) {
            Vec3 row{}, rowv{};
            for (int j = 0; j <= Q; ++j) {
                const HPoint& h = b.at(i, j);
                const Vec3 c{h.x, h.y, h.z};
                row = row + Bv[j] * c;
                rowv = rowv + dBv[j] * c;
            }
            X = X + Bu[i] * row;
            Xu = Xu + dBu[i] * row;
            Xv = Xv + Bu[i] * rowv;
        }
        return {X, Xu, Xv};
    }
}

// enclose_homogeneous() (bezier_patch.h) of fixed degrees: the same
// operations per coordinate in the same order (so the same enclosures), the
// four coordinates two lanes at a time, (x, y) and (z, w), held in registers
// (the generic loops' stack arrays cost a store-forwarding stall per level).
//
// Frame: also the point and its partial derivatives in doubles into *frame,
// from the same de Casteljau levels (X_t = Q (b_1 - b_0) of each row's last
// level but one, reduced along s as the rows are; X_s = P (c_1 - c_0) of the
// columns' last level but one) and the quotient rule as evaluate()'s. The
// enclosures are the same bits either way (single pixels: one pass serves
// Newton's certificate and the shading, instead of evaluate() again).
template <int P, int Q, bool Frame = false>
void enclose_homogeneous_fixed(const BezierPatch& b, double s, double t, int dims, Interval* out,
                               SurfacePoint* frame = nullptr) {
    using Lanes = double __attribute__((vector_size(16)));
    constexpr double u = 0x1p-53;
    constexpr int levels = P + Q;
    const double rs = 1.0 - s, rt = 1.0 - t;
    const Lanes sign = {-0.0, -0.0};
    Lanes M[2] = {}, col[P + 1][2], tcol[P + 1][2], Xs[2];
    for (int i = 0; i <= P; ++i) {
        Lanes row[Q + 1][2];
        for (int j = 0; j <= Q; ++j) {
            const HPoint& h = b.at(i, j);
            row[j][0] = Lanes{h.x, h.y};
            row[j][1] = Lanes{h.z, h.w};
            for (int k = 0; k < 2; ++k) {
                // |x| by clearing the sign; M < a ? a : M is std::max(M, a).
                using Bits = long long __attribute__((vector_size(16)));
                const Lanes a = Lanes(Bits(row[j][k]) & ~Bits(sign));
                M[k] = M[k] < a ? a : M[k];
            }
        }
        for (int l = 1; l <= Q; ++l) {
            if constexpr (Frame)
                if (l == Q)
                    for (int k = 0; k < 2; ++k) tcol[i][k] = double(Q) * (row[1][k] - row[0][k]);
            for (int j = 0; j <= Q - l; ++j)
                for (int k = 0; k < 2; ++k) row[j][k] = rt * row[j][k] + t * row[j + 1][k];
        }
        col[i][0] = row[0][0];
        col[i][1] = row[0][1];
    }
    for (int l = 1; l <= P; ++l) {
        if constexpr (Frame) {
            if (l == P)
                for (int k = 0; k < 2; ++k) Xs[k] = double(P) * (col[1][k] - col[0][k]);
            for (int i = 0; i <= P - l; ++i)
                for (int k = 0; k < 2; ++k) tcol[i][k] = rs * tcol[i][k] + s * tcol[i + 1][k];
        }
        for (int i = 0; i <= P - l; ++i)
            for (int k = 0; k < 2; ++k) col[i][k] = rs * col[i][k] + s * col[i + 1][k];
    }
    for (int c = 0; c < dims; ++c) {
        const double v = col[0][c / 2][c % 2];
        double e = 4 * u * levels * M[c / 2][c % 2] + underflow_allowance(3.0 * levels);
        e = next_up(next_up(e));
        out[c] = std::isfinite(v) && std::isfinite(e) ? Interval(next_down(v - e), next_up(v + e))
                                                      : Interval::entire();
    }
    if constexpr (Frame) {
        // Quotient rule: P = X/W, P_s = (X_s - P W_s) / W.
        const double w = col[0][1][1];
        frame->point = Vec3{col[0][0][0], col[0][0][1], col[0][1][0]} / w;
        frame->du = (Vec3{Xs[0][0], Xs[0][1], Xs[1][0]} - Xs[1][1] * frame->point) / w;
        frame->dv =
            (Vec3{tcol[0][0][0], tcol[0][0][1], tcol[0][1][0]} - tcol[0][1][1] * frame->point) / w;
    }
}

// The primary ray's homogeneous system G = (X - a Z, Y - b Z) of a patch and
// its partials along s and t at one point, in doubles. Its zeros are the
// ray's hits (W > 0), and Newton on G needs no quotient.
struct RaySystemAt {
    double G[2], Gs[2], Gt[2];
};

// RaySystemAt of patch b for the ray's (a, bb) at (s, t). Each control point
// is combined with the ray first, so the sums run over two coordinates (one
// lane pair) instead of four. Inlined, like bernstein_fixed: G's arrays stay
// in registers.
template <int P, int Q>
[[gnu::always_inline]] inline RaySystemAt ray_system_fixed(const BezierPatch& b, double a,
                                                           double bb, double s, double t) {
    using Lanes = double __attribute__((vector_size(16)));
    double Bu[P + 1], dBu[P + 1], Bv[Q + 1], dBv[Q + 1];
    bernstein_fixed<P>(s, Bu, dBu);
    bernstein_fixed<Q>(t, Bv, dBv);
    const Lanes e = {a, bb};
    Lanes X = {}, Xu = {}, Xv = {};
    for (int i = 0; i <= P; ++i) {
        Lanes row = {}, rowv = {};
        for (int j = 0; j <= Q; ++j) {
            const HPoint& h = b.at(i, j);
            const Lanes c = Lanes{h.x, h.y} - e * h.z;
            row = row + Bv[j] * c;
            rowv = rowv + dBv[j] * c;
        }
        X = X + Bu[i] * row;
        Xu = Xu + dBu[i] * row;
        Xv = Xv + Bu[i] * rowv;
    }
    RaySystemAt r;
    for (int k = 0; k < 2; ++k) {
        r.G[k] = X[k];
        r.Gs[k] = Xu[k];
        r.Gt[k] = Xv[k];
    }
    return r;
}

} // namespace seamless
