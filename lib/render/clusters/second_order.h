// SPDX-License-Identifier: MIT
// INTRACY step 9 with a second-order criterion (paper section 7, step 9 and
// remark 2). Step 9 paints a certified cluster B with the bilinear form L of
// its four corner intensities plus dither, which the paper allows when the
// intensity enclosure of B spans at most two levels. Highlights and shading
// gradients make that enclosure wide although the intensity I is smooth and L
// fits it closely. This criterion bounds |I - L| over B instead.
//
// The bound. Let c_k be the screen points of B's corner pixels, W_a, W_b the
// width and height of the rectangle R they span, and x = (x_a, x_b) a pixel
// of B at fractions (u, v) in [0,1]^2 between the corner columns and rows. L
// interpolates linearly along a and then along b, so with P_a f the linear
// interpolant of f along a at fixed b (P_b alike),
//   I - L = (I - P_a I) + P_a (I - P_b I),
// where (I - P_a I)(x) is the error of linear interpolation along the row
// through x, and P_a (I - P_b I)(x) = (1 - u) E(c_a0) + u E(c_a1) is a convex
// combination of such errors along B's first and last columns (E: the
// interpolation error along b at x_b). The mixed partial I_ab never enters.
// One dimension, f on [x0, x1] of width W at fraction u, l its interpolant:
//  (first order) if f is Lipschitz with f' in g0 + [-r, r] a.e., then
//    f(x) - l(x) = (1 - u) (f(x) - f(x0)) + u (f(x) - f(x1)), and the g0 parts
//    (1 - u) u W g0 - u (1 - u) W g0 cancel: |f - l| <= 2 u (1 - u) W r;
//  (second order) if f' is Lipschitz with |f''| <= M a.e., then
//    |f - l| <= u (1 - u) W^2 M / 2 (Peano kernel of linear interpolation,
//    which is <= 0 and integrates to -u (1 - u) W^2 / 2).
// Both hold for each of the two terms, and u (1 - u) <= 1 / 4, so with the
// gradient of I over R in g0 + [-r_a, r_a] x [-r_b, r_b] and |I_aa| <= M_a,
// |I_bb| <= M_b over R where I is C^2 there (interval_jet2.h; the second-order
// parts are entire otherwise),
//   |I(x) - L(x)| <= min(r_a W_a / 2, M_a W_a^2 / 8)
//                  + min(r_b W_b / 2, M_b W_b^2 / 8).
// The second-order parts converge to |I_aa| and |I_bb| as B shrinks, while
// interval arithmetic overestimates r by the width of the gradient's enclosure
// (many times the sampled variation: docs/results/render.md).
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
#include <seamless/render/clusters/surface_jets.h>
#include <seamless/render/pixels/pixel_solve.h>
#include <seamless/render/scene/projection.h>
#include <seamless/render/scene/render_options.h>
#include <seamless/render/scene/render_stats.h>
#include <seamless/render/shading/interval_jet2.h>
#include <seamless/render/shading/shading.h>
#include <seamless/render/subscreen/primary_cluster.h>

#include <array>
#include <cmath>

namespace seamless {

// The bound of the comment above, rounded up: |I - L| over B for the
// intensity jet I; wa, wb: W_a, W_b.
double bilinear_error(const IntervalJet2& I, double wa, double wb);

// What a cluster's rays see: the ambient and the lights that reach every ray
// of B (camera coordinates), and the patch's material.
struct ClusterLight {
    const Scene& lighting;
    const Material& mat;
};

// The certified intensity of one corner ray of cluster c (the ray through
// screen point (a, b), hitting c.pp exactly once in c.box): the hit
// certified by newton_hit (certified_newton.h) on a small box, SHADE over that box.
// J: the Jacobian over c.box for every ray of B. false when not certified.
bool corner_intensity(const CertifiedCluster& c, const ClusterLight& light, RVec<2> ab,
                      const MarkJacobian& J, ClusterSystem& scratch, RenderStats& st,
                      std::array<Interval, 3>& I);

// The intensity of the rays of a cluster as second-order jets over B:
// shade<IntervalJet2> (shading.h) at the jets of surface_jets.h; [0, 1] with
// entire partials where those are undecided; A, a, b as surface_jets'.
// (Splitting `box` into 3 x 3 parts and taking the hull of their first-order
// jets narrowed the first-order bound a little but cost more than it saved:
// docs/results/render.md.)
std::array<IntervalJet2, 3> intensity_jets(const CertifiedCluster& c, const ClusterLight& light,
                                           const IMat<2>& A, Interval a, Interval b);

// The second-order test of a cluster whose plain step 9 failed on span.
struct SecondOrder {
    bool paint = false;
    std::array<double, 3> corner[4]; // intensities to interpolate (B's corners, row by row)
    double error_levels = 0;         // e of the comment above (in levels), the widest channel
    std::array<double, 3> bound{};   // |I - L| over B per channel (intensity)
};
// B's corner pixels: the screen coordinates of its first and last pixel
// column (a) and row (b).
struct CornerPixels {
    double a[2], b[2];
};
// Step 9's painting rule: the image's levels, and whether it dithers.
struct PaintRule {
    int levels;
    bool dither;
};
// c: the certified cluster (box contracted by certify_cluster); light: what its rays see.
SecondOrder second_order(const CertifiedCluster& c, const ClusterLight& light,
                         const CornerPixels& corners, PaintRule rule, ClusterSystem& scratch,
                         RenderStats& st);

// Step 9's bilinear form of B's corner intensities (corner[0..3], row by row:
// (x0, y0), (x1, y0), (x0, y1), (x1, y1)), painted with `levels` levels.
struct BilinearForm {
    const std::array<double, 3>* corner;
    int levels;
    // Channel c's painted level at fractions (fx, fy) between B's corner
    // pixels: the form plus dither d, rounded and kept within [lo, hi].
    int level(int c, double fx, double fy, double d, int lo, int hi) const {
        const double v = (1 - fy) * ((1 - fx) * corner[0][c] + fx * corner[1][c]) +
                         fy * ((1 - fx) * corner[2][c] + fx * corner[3][c]);
        // std::lround without the library call: for x > 0 the truncation is the
        // floor and x - floor(x) is exact, so this rounds halves away from zero
        // too; x <= 0 gives 0 where lround gives 0 or less, the same after the
        // clamp to [lo, hi] (lo >= 0).
        const double x = clamp01(v) * (levels - 1) + d;
        long level = x > 0 ? static_cast<long>(x) : 0;
        if (x - static_cast<double>(level) >= 0.5) ++level;
        return static_cast<int>(std::clamp<long>(level, lo, hi));
    }
};

} // namespace seamless
