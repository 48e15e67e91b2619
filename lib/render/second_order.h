// SPDX-License-Identifier: MIT
// INTRACY step 9 with a second-order criterion (paper section 7, step 9 and
// remark 2). Step 9 paints a certified cluster B with the bilinear form L of
// its four corner intensities plus dither, which the paper allows when the
// intensity enclosure of B spans at most two levels. Highlights and shading
// gradients make that enclosure wide although the intensity I is smooth and L
// fits it closely. This criterion bounds |I - L| over B instead.
//
// The bound. Let c_k be the screen points of B's corner pixels, W_a, W_b the
// width and height of the rectangle they span, and x a pixel of B with
// bilinear weights w_k(x) >= 0, sum w_k = 1, sum w_k c_k = x (bilinear
// interpolation reproduces affine functions). If the gradient of I over B lies
// in the box g0 + [-r_a, r_a] x [-r_b, r_b] (interval_jet.h; I need only be
// Lipschitz), then along each segment from c_k to x
//   I(x) - I(c_k) = (g0 + delta_k) . (x - c_k),  |delta_k,i| <= r_i,
// and since sum w_k g0 . (x - c_k) = g0 . (x - sum w_k c_k) = 0,
//   |I(x) - L(x)| <= sum_k w_k (r_a |x_a - c_k,a| + r_b |x_b - c_k,b|)
//                  = 2 u (1 - u) r_a W_a + 2 v (1 - v) r_b W_b
//                 <= (r_a W_a + r_b W_b) / 2,
// where (u, v) in [0,1]^2 are x's fractions between the corner columns and rows.
//
// The painted level. With n levels, I' = I (n - 1), the painted value is
// V = L~ (n - 1) from corner values L~ that enclose the true corner
// intensities within e_c (certified corner hits, interval SHADE at them), so
// |V - I'| <= e := (n - 1) (bound + e_c) + rounding. The pixel is painted
// p = round(V + d) with dither d in [-0.5, 0.5) (0 without dither) and kept
// in the enclosure's levels [lo, hi]. Claim: if e < 1 - max|d| (e < 0.5 with
// dither, e < 1 without), then |p - q| <= 1 for the true level q = round(I').
// Proof: I' >= 0 and q = floor(I' + 0.5), so q - 0.5 <= I' < q + 0.5.
// V + d > I' - e - 0.5 >= I' - 1 >= q - 1.5, so round(V + d) >= q - 1 (floor
// is monotone; a negative V + d rounds to <= 0 but then q <= 1 and p >= lo >=
// 0 >= q - 1). V + d < I' + e + 0.5 <= I' + 1 < q + 1.5, so round(V + d) <=
// q + 1. Clamping p into [lo, hi], which holds q, moves it only towards q.
#pragma once

#include <seamless/interval/interval_matrix.h>
#include <seamless/render/interval_jet.h>
#include <seamless/render/pixel_solve.h>
#include <seamless/render/primary_cluster.h>
#include <seamless/render/projection.h>
#include <seamless/render/render.h>
#include <seamless/render/shading.h>

#include <array>
#include <cmath>

namespace seamless {

// The camera-space point and (unnormalised) normal P_s x P_t of the hits of
// the rays of a certified cluster, as functions of the screen point (a, b):
// values and partials over B. By the implicit function theorem on the
// homogeneous system G = (X - a Z, Y - b Z) = 0: d(s, t)/da = A^-1 (Z, 0),
// d(s, t)/db = A^-1 (0, Z), A = dG/d(s, t) over the cluster (regular by step
// 7's certificate); then the chain rule through the normal and P's second
// derivatives. The point itself moves along its ray (second_order.cpp).
// A: the interval Jacobian of G over `box` for every ray of B; e: enclose(f,
// box); a, b: B's screen coordinates (the hull of its pixels' centres). false
// when A's enclosed determinant may vanish.
bool surface_jets(const PatchForms& f, const ParamBox& box, const PatchEnclosure& e,
                  const IMat<2>& A, Interval a, Interval b, V3<IntervalJet>& P, V3<IntervalJet>& N);

// (r_a W_a + r_b W_b) / 2 of the comment above, rounded up: the bound on
// |I - L| over B for the intensity jet I; wa, wb: W_a, W_b.
double bilinear_error(const IntervalJet& I, double wa, double wb);

// The certified intensity of one corner ray of a cluster (the ray through
// screen point (a, b), hitting patch pp exactly once in `box`): the hit
// certified by newton_hit (pixel_solve.h) on a small box, SHADE over that box.
// J: the Jacobian over box for every ray of B. false when not certified.
bool corner_intensity(const ProjectedPatch& pp, const Scene& lighting, const Material& mat,
                      double a, double b, const ParamBox& box, const MarkJacobian& J,
                      ClusterSystem& scratch, RenderStats& st, std::array<Interval, 3>& I);

// The intensity of the rays of a cluster as jets over B: shade<IntervalJet>
// (shading.h) at the jets of surface_jets; [0, 1] with entire partials where
// those are undecided. (Splitting `box` into 3 x 3 parts and taking the hull of
// their jets narrowed the bound a little but cost more than it saved:
// docs/results/render.md, fifth round.)
std::array<IntervalJet, 3> intensity_jets(const ProjectedPatch& pp, const Scene& lighting,
                                          const Material& mat, const ParamBox& box,
                                          const PatchEnclosure& e, const IMat<2>& A, Interval a,
                                          Interval b);

// The second-order test of a cluster whose plain step 9 failed on span.
struct SecondOrder {
    bool paint = false;
    std::array<double, 3> corner[4]; // intensities to interpolate (B's corners, row by row)
    double error_levels = 0;         // e of the comment above (in levels), the widest channel
    std::array<double, 3> bound{};   // |I - L| over B per channel (intensity)
};
// pp, box, sys: the certified cluster (box contracted by certify_cluster, sys
// its cluster system); e: enclose(pp.forms, box); lighting: the lights that reach every ray of B
// (camera coordinates), mat: the patch's material; ca, cb: screen coordinates of B's first and last
// pixel column and row.
SecondOrder second_order(const ProjectedPatch& pp, const Scene& lighting, const Material& mat,
                         const ParamBox& box, const PatchEnclosure& e, const ClusterSystem& sys,
                         const double ca[2], const double cb[2], int levels, bool dither,
                         ClusterSystem& scratch, RenderStats& st);

// Step 9's painted level at fractions (fx, fy) between B's corner pixels: the
// bilinear form of the corner intensities (row by row: (x0, y0), (x1, y0),
// (x0, y1), (x1, y1)) plus dither d, rounded and kept within [lo, hi].
inline int bilinear_level(const std::array<double, 3> corner[4], int c, double fx, double fy,
                          double d, int levels, int lo, int hi) {
    const double v = (1 - fy) * ((1 - fx) * corner[0][c] + fx * corner[1][c]) +
                     fy * ((1 - fx) * corner[2][c] + fx * corner[3][c]);
    const long level = std::lround(clamp01(v) * (levels - 1) + d);
    return static_cast<int>(std::clamp<long>(level, lo, hi));
}

} // namespace seamless
