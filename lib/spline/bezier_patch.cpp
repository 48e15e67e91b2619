// SPDX-License-Identifier: MIT
#include <seamless/spline/bezier_patch.h>
#include <seamless/spline/fixed_degree.h>

#include <seamless/base/check.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace seamless {

void bernstein(int n, double s, double* B, double* dB) {
    // Degree n-1 values first (for the derivative), then one more step.
    double tmp[BezierPatch::kMaxOrder];
    tmp[0] = 1.0;
    const double r = 1.0 - s;
    for (int d = 1; d < n; ++d) {
        double prev = 0.0;
        for (int i = 0; i < d; ++i) {
            double t = tmp[i];
            tmp[i] = prev + r * t;
            prev = s * t;
        }
        tmp[d] = prev;
    }
    if (n == 0) {
        B[0] = 1;
        dB[0] = 0;
        return;
    }
    // tmp holds B^{n-1}. d/ds B_i^n = n (B_{i-1}^{n-1} - B_i^{n-1}).
    for (int i = 0; i <= n; ++i) {
        double a = i >= 1 ? tmp[i - 1] : 0.0;
        double b = i <= n - 1 ? tmp[i] : 0.0;
        B[i] = s * a + r * b;
        dB[i] = n * (a - b);
    }
}

namespace {

// X(s,t) and its partial derivatives in homogeneous coordinates.
void homogeneous_derivatives(const BezierPatch& b, double s, double t, HPoint& X, HPoint& Xu,
                             HPoint& Xv) {
    double Bu[BezierPatch::kMaxOrder], dBu[BezierPatch::kMaxOrder];
    double Bv[BezierPatch::kMaxOrder], dBv[BezierPatch::kMaxOrder];
    bernstein(b.p, s, Bu, dBu);
    bernstein(b.q, t, Bv, dBv);
    X = Xu = Xv = HPoint{0, 0, 0, 0};
    for (int i = 0; i <= b.p; ++i) {
        HPoint row{0, 0, 0, 0}, rowv{0, 0, 0, 0};
        for (int j = 0; j <= b.q; ++j) {
            row = row + Bv[j] * b.at(i, j);
            rowv = rowv + dBv[j] * b.at(i, j);
        }
        X = X + Bu[i] * row;
        Xu = Xu + dBu[i] * row;
        Xv = Xv + Bu[i] * rowv;
    }
}

} // namespace

HPoint evaluate_homogeneous(const BezierPatch& b, double s, double t) {
    HPoint X, Xu, Xv;
    homogeneous_derivatives(b, s, t, X, Xu, Xv);
    return X;
}

void enclose_homogeneous(const BezierPatch& b, double s, double t, int dims, Interval* out) {
    // Bicubic, biquadratic, bilinear: the same operations, unrolled in
    // registers (fixed_degree.h).
    if (b.p == b.q) {
        if (b.p == 3) return enclose_homogeneous_fixed<3, 3>(b, s, t, dims, out);
        if (b.p == 2) return enclose_homogeneous_fixed<2, 2>(b, s, t, dims, out);
        if (b.p == 1) return enclose_homogeneous_fixed<1, 1>(b, s, t, dims, out);
    }
    enclose_homogeneous_any_degree(b, s, t, dims, out);
}

void enclose_homogeneous(const BezierPatch& b, double s, double t, int dims, Interval* out,
                         SurfacePoint& frame) {
    if (b.p == b.q) {
        if (b.p == 3) return enclose_homogeneous_fixed<3, 3, true>(b, s, t, dims, out, &frame);
        if (b.p == 2) return enclose_homogeneous_fixed<2, 2, true>(b, s, t, dims, out, &frame);
        if (b.p == 1) return enclose_homogeneous_fixed<1, 1, true>(b, s, t, dims, out, &frame);
    }
    enclose_homogeneous_any_degree(b, s, t, dims, out);
    frame = evaluate(b, s, t);
}

void enclose_homogeneous_any_degree(const BezierPatch& b, double s, double t, int dims,
                                    Interval* out) {
    SEAMLESS_CHECK(s >= 0 && s <= 1 && t >= 0 && t <= 1, "the error bound holds in [0,1]^2");
    constexpr double u = 0x1p-53;
    const double rs = 1.0 - s, rt = 1.0 - t;
    const int levels = b.p + b.q;
    for (int c = 0; c < dims; ++c) {
        double M = 0, row[BezierPatch::kMaxOrder], col[BezierPatch::kMaxOrder];
        for (int i = 0; i <= b.p; ++i) {
            for (int j = 0; j <= b.q; ++j) {
                row[j] = b.at(i, j)[c];
                M = std::max(M, std::abs(row[j]));
            }
            for (int k = 1; k <= b.q; ++k)
                for (int j = 0; j <= b.q - k; ++j) row[j] = rt * row[j] + t * row[j + 1];
            col[i] = row[0];
        }
        for (int k = 1; k <= b.p; ++k)
            for (int i = 0; i <= b.p - k; ++i) col[i] = rs * col[i] + s * col[i + 1];
        const double v = col[0];
        double e = 4 * u * levels * M + underflow_allowance(3.0 * levels);
        e = next_up(next_up(e));
        out[c] = std::isfinite(v) && std::isfinite(e) ? Interval(next_down(v - e), next_up(v + e))
                                                      : Interval::entire();
    }
}

namespace {

// evaluate_point below with the degrees known at compile time: the same
// operations, unrolled (a trimmed face's samples evaluate low-degree patches
// hundreds of thousands of times: span_patches.h).
template <int P, int Q> Vec3 evaluate_point_fixed(const BezierPatch& b, double s, double t) {
    double Bu[P + 1], dBu[P + 1], Bv[Q + 1], dBv[Q + 1];
    bernstein_fixed<P>(s, Bu, dBu);
    bernstein_fixed<Q>(t, Bv, dBv);
    double x = 0, y = 0, z = 0, w = 0;
    for (int i = 0; i <= P; ++i) {
        double rx = 0, ry = 0, rz = 0, rw = 0;
        for (int j = 0; j <= Q; ++j) {
            const HPoint& h = b.at(i, j);
            rx += Bv[j] * h.x, ry += Bv[j] * h.y, rz += Bv[j] * h.z, rw += Bv[j] * h.w;
        }
        x += Bu[i] * rx, y += Bu[i] * ry, z += Bu[i] * rz, w += Bu[i] * rw;
    }
    return b.rational ? Vec3{x / w, y / w, z / w} : Vec3{x, y, z};
}

} // namespace

Vec3 evaluate_point(const BezierPatch& b, double s, double t) {
    switch (b.p * 10 + b.q) {
    case 11:
        return evaluate_point_fixed<1, 1>(b, s, t);
    case 12:
        return evaluate_point_fixed<1, 2>(b, s, t);
    case 21:
        return evaluate_point_fixed<2, 1>(b, s, t);
    case 22:
        return evaluate_point_fixed<2, 2>(b, s, t);
    case 23:
        return evaluate_point_fixed<2, 3>(b, s, t);
    case 32:
        return evaluate_point_fixed<3, 2>(b, s, t);
    case 33:
        return evaluate_point_fixed<3, 3>(b, s, t);
    default:
        break;
    }
    double Bu[BezierPatch::kMaxOrder], Bv[BezierPatch::kMaxOrder], unused[BezierPatch::kMaxOrder];
    bernstein(b.p, s, Bu, unused);
    bernstein(b.q, t, Bv, unused);
    double x = 0, y = 0, z = 0, w = 0;
    for (int i = 0; i <= b.p; ++i) {
        double rx = 0, ry = 0, rz = 0, rw = 0;
        for (int j = 0; j <= b.q; ++j) {
            const HPoint& h = b.at(i, j);
            rx += Bv[j] * h.x, ry += Bv[j] * h.y, rz += Bv[j] * h.z, rw += Bv[j] * h.w;
        }
        x += Bu[i] * rx, y += Bu[i] * ry, z += Bu[i] * rz, w += Bu[i] * rw;
    }
    return b.rational ? Vec3{x / w, y / w, z / w} : Vec3{x, y, z};
}

SurfacePoint evaluate(const BezierPatch& b, double s, double t) {
    // Bicubic, biquadratic, bilinear: the same operations as below, unrolled
    // (fixed_degree.h).
    if (b.p == b.q) {
        if (b.p == 3) return evaluate_fixed<3, 3, true>(b, s, t);
        if (b.p == 2) return evaluate_fixed<2, 2, true>(b, s, t);
        if (b.p == 1) return evaluate_fixed<1, 1, true>(b, s, t);
    }
    HPoint X, Xu, Xv;
    homogeneous_derivatives(b, s, t, X, Xu, Xv);
    // Quotient rule: P = X/W, P_s = (X_s - P W_s) / W.
    SurfacePoint r;
    r.point = X.xyz() / X.w;
    r.du = (Xu.xyz() - Xu.w * r.point) / X.w;
    r.dv = (Xv.xyz() - Xv.w * r.point) / X.w;
    return r;
}

namespace {

// split() along D: de Casteljau's levels run over one index of cp (stride
// apart), once for each line of the other index (line_stride apart).
template <Direction D>
void split_along(const BezierPatch& b, double x, BezierPatch& lo, BezierPatch& hi) {
    constexpr bool along_u = D == Direction::u;
    constexpr int stride = along_u ? BezierPatch::kMaxOrder : 1;
    constexpr int line_stride = along_u ? 1 : BezierPatch::kMaxOrder;
    // The parameter range split (a0, a1) and the one kept (c0, c1).
    constexpr double BezierPatch::*a0 = along_u ? &BezierPatch::u0 : &BezierPatch::v0;
    constexpr double BezierPatch::*a1 = along_u ? &BezierPatch::u1 : &BezierPatch::v1;
    constexpr double BezierPatch::*c0 = along_u ? &BezierPatch::v0 : &BezierPatch::u0;
    constexpr double BezierPatch::*c1 = along_u ? &BezierPatch::v1 : &BezierPatch::u1;
    const int p = b.p, q = b.q;
    const int n = along_u ? p : q, lines = along_u ? q : p;
    for (BezierPatch* h : {&lo, &hi}) {
        h->p = p;
        h->q = q;
        h->rational = b.rational;
        h->surface = b.surface;
        h->*c0 = b.*c0;
        h->*c1 = b.*c1;
    }
    const double m = b.*a0 + x * (b.*a1 - b.*a0); // b.u_at(x) or b.v_at(x)
    lo.*a0 = b.*a0;
    lo.*a1 = m;
    hi.*a0 = m;
    hi.*a1 = b.*a1;
    HPoint line[BezierPatch::kMaxOrder];
    for (int l = 0; l <= lines; ++l) {
        const int first = l * line_stride;
        for (int k = 0; k <= n; ++k) line[k] = b.cp[first + k * stride];
        // De Casteljau: lo gets the first point of each level, hi the last.
        for (int level = 0; level <= n; ++level) {
            lo.cp[first + level * stride] = line[0];
            hi.cp[first + (n - level) * stride] = line[n - level];
            for (int k = 0; k < n - level; ++k) line[k] = lerp(line[k], line[k + 1], x);
        }
    }
}

} // namespace

void split(const BezierPatch& b, Direction d, double x, BezierPatch& lo, BezierPatch& hi) {
    if (d == Direction::u)
        split_along<Direction::u>(b, x, lo, hi);
    else
        split_along<Direction::v>(b, x, lo, hi);
}

Box3 control_box(const BezierPatch& b) {
    Box3 box;
    for (int i = 0; i <= b.p; ++i)
        for (int j = 0; j <= b.q; ++j) box.extend(b.point(i, j));
    return box;
}

} // namespace seamless
