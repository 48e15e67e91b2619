// SPDX-License-Identifier: MIT
#include <seamless/render/clusters/second_order.h>

#include <algorithm>
#include <limits>

namespace seamless {
namespace {

V3<Interval> v3(const IVec3& a) {
    return {a[0], a[1], a[2]};
}

// min(r W / 2, M W^2 / 8) of second_order.h for one direction, rounded up; d,
// dd: the jet's first and second partial along it.
double direction_error(Interval d, Interval dd, double w) {
    const Interval W(w);
    const double first = (Interval(d.rad()) * W * Interval(0.5)).hi();
    const double second = (Interval(dd.mag()) * sqr(W) * Interval(0.125)).hi();
    return std::min(first, second); // NaN-free: rad and mag of finite or entire intervals
}

// Coordinate c of a power form over a box by nested interval Horner. On a
// corner's hit box (newton_hit's, about 1e-13 wide) it is as tight as
// enclose()'s Horner with Lemma 2 intersected with the mean value form, to
// within a few roundings, at a fraction of their cost.
Interval nested_horner(const PowerForm& f, int c, const ParamBox& box) {
    Interval r(0.0);
    for (int i = f.p; i >= 0; --i) {
        Interval row(0.0);
        for (int j = f.q; j >= 0; --j) row = row * box.t + f.at(c, i, j);
        r = r * box.s + row;
    }
    return r;
}

// Point and normal over a corner's hit box: nested Horner on X, X_s and X_t;
// a rational patch's P = X / W with W within [min w_ij, max w_ij] and the
// quotient rule P_s = (X_s - P W_s) / W, as in enclose() (enclosure.h).
void corner_frame(const PatchForms& f, const ParamBox& box, V3<Interval>& P, V3<Interval>& N) {
    IVec3 X, Xs, Xt;
    for (int c = 0; c < 3; ++c) {
        X[c] = nested_horner(f.X, c, box);
        Xs[c] = nested_horner(f.Xs, c, box);
        Xt[c] = nested_horner(f.Xt, c, box);
    }
    if (f.rational) {
        const Interval W = intersect(nested_horner(f.X, 3, box), f.w_hull);
        const Interval Ws = nested_horner(f.Xs, 3, box), Wt = nested_horner(f.Xt, 3, box);
        for (int c = 0; c < 3; ++c) {
            X[c] = X[c] / W;
            Xs[c] = (Xs[c] - X[c] * Ws) / W;
            Xt[c] = (Xt[c] - X[c] * Wt) / W;
        }
    }
    for (int c = 0; c < 3; ++c) X[c] = intersect(X[c], f.control_hull[c]);
    P = v3(X);
    N = v3(cross(Xs, Xt));
}

} // namespace

double bilinear_error(const IntervalJet2& I, double wa, double wb) {
    if (!I.da.is_finite() || !I.db.is_finite()) return std::numeric_limits<double>::infinity();
    return (Interval(direction_error(I.da, I.daa, wa)) + Interval(direction_error(I.db, I.dbb, wb)))
        .hi();
}

bool corner_intensity(const CertifiedCluster& c, const ClusterLight& light, RVec<2> ab,
                      const MarkJacobian& J, ClusterSystem& scratch, RenderStats& st,
                      std::array<Interval, 3>& I) {
    const ProjectedPatch& pp = c.pp;
    const ParamBox& box = c.box;
    RaySystem sys(pp, ab[0], ab[1], scratch);
    CertifiedHit hit;
    if (!newton_hit(sys, box, J, hit, st)) return false;
    ++st.primary_rays;
    V3<Interval> P, N;
    corner_frame(pp.forms, hit.box, P, N);
    I = shade<Interval>(light.lighting, light.mat, P, N, Vec3{});
    return I[0].is_finite() && I[1].is_finite() && I[2].is_finite();
}

std::array<IntervalJet2, 3> intensity_jets(const CertifiedCluster& c, const ClusterLight& light,
                                           const IMat<2>& A, Interval a, Interval b) {
    V3<IntervalJet2> P, N;
    if (!surface_jets(c, A, a, b, P, N)) {
        const IntervalJet2 any = unit_range(IntervalJet2());
        return {any, any, any};
    }
    return shade<IntervalJet2>(light.lighting, light.mat, P, N, Vec3{});
}

SecondOrder second_order(const CertifiedCluster& cluster, const ClusterLight& light,
                         const CornerPixels& corners, PaintRule rule, ClusterSystem& scratch,
                         RenderStats& st) {
    const double* ca = corners.a;
    const double* cb = corners.b;
    const int levels = rule.levels;
    const bool dither = rule.dither;
    SecondOrder r;
    const Interval a = Interval::hull(ca[0], ca[1]), b = Interval::hull(cb[0], cb[1]);
    const MarkJacobian J = mark_jacobian(cluster.sys, cluster.box);
    const std::array<IntervalJet2, 3> I = intensity_jets(cluster, light, J.A, a, b);
    const double wa = (Interval(ca[1]) - Interval(ca[0])).mag();
    const double wb = (Interval(cb[1]) - Interval(cb[0])).mag();
    const double limit = dither ? 0.5 : 1.0;
    const Interval n1(levels - 1.0);
    for (int c = 0; c < 3; ++c) {
        r.bound[c] = bilinear_error(I[c], wa, wb);
        r.error_levels = std::max(r.error_levels, (n1 * Interval(r.bound[c])).hi());
    }
    // Without the corners' own widths: a cheap early exit.
    if (!(r.error_levels < limit)) return r;
    r.error_levels = 0;
    // The corners: certified hits, interval SHADE there; painted from the
    // midpoints, which are within rad of the true corner intensities.
    double corner_rad[3] = {0, 0, 0};
    for (int k = 0; k < 4; ++k) {
        std::array<Interval, 3> Ic;
        if (!corner_intensity(cluster, light, RVec<2>{ca[k & 1], cb[k >> 1]}, J, scratch, st, Ic))
            return r;
        for (int c = 0; c < 3; ++c) {
            r.corner[k][c] = Ic[c].mid();
            corner_rad[c] = std::max(corner_rad[c], Ic[c].rad());
        }
    }
    // Rounding: the bilinear form and the scaling in doubles (values in
    // [0, 1]: a few ulps of 1, far below 1e-12), and the pixels' screen points
    // computed in doubles rather than the exact affine fractions between the
    // corners (relative 1e-15 of coordinates of magnitude < 1e3), times the
    // gradient's magnitude.
    bool ok = true;
    for (int c = 0; c < 3; ++c) {
        const Interval slack =
            Interval(1e-12) * (Interval(1.0) + Interval(I[c].da.mag()) + Interval(I[c].db.mag()));
        const double err = (n1 * (Interval(r.bound[c]) + Interval(corner_rad[c]) + slack)).hi();
        r.error_levels = std::max(r.error_levels, err);
        ok &= err < limit;
    }
    r.paint = ok;
    return r;
}

} // namespace seamless
