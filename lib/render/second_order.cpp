// SPDX-License-Identifier: MIT
#include <seamless/render/second_order.h>

#include <algorithm>

namespace seamless {
namespace {

V3<Interval> v3(const IVec3& a) {
    return {a[0], a[1], a[2]};
}
// a x b for interval vectors held as V3.
V3<Interval> cross3(const V3<Interval>& a, const V3<Interval>& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
// u s_x + w t_x: a derivative along the screen from those along s and t.
V3<Interval> along(const V3<Interval>& u, Interval s_x, const V3<Interval>& w, Interval t_x) {
    return {u.x * s_x + w.x * t_x, u.y * s_x + w.y * t_x, u.z * s_x + w.z * t_x};
}

} // namespace

bool surface_jets(const PatchForms& f, const ParamBox& box, const PatchEnclosure& e,
                  const IMat<2>& A, Interval a, Interval b, V3<IntervalJet>& P,
                  V3<IntervalJet>& N) {
    const Interval det = A(0, 0) * A(1, 1) - A(0, 1) * A(1, 0);
    if (det.contains(0.0)) return false;
    // Homogeneous depth: G_a = (-Z, 0), G_b = (0, -Z) with Z = X_2 (times W).
    const Interval Zd = horner(f.X, 2, box) / det;
    const Interval s_a = A(1, 1) * Zd, t_a = -(A(1, 0) * Zd);
    const Interval s_b = -(A(0, 1) * Zd), t_b = A(0, 0) * Zd;
    const PatchSecondDerivatives d2 = enclose_second(f, box, e);
    const V3<Interval> Ps = v3(e.ds), Pt = v3(e.dt);
    // N = P_s x P_t: N_s = P_ss x P_t + P_s x P_st, N_t = P_st x P_t + P_s x P_tt.
    const V3<Interval> Ns = cross3(v3(d2.ss), Pt) + cross3(Ps, v3(d2.st));
    const V3<Interval> Nt = cross3(v3(d2.st), Pt) + cross3(Ps, v3(d2.tt));
    // The point moves along its ray d = (a, b, 1): P = Z d, and P_a, P_b are
    // tangent (N . P_a = 0), so Z_a = -Z N_x / (N . d), Z_b = -Z N_y / (N . d):
    // far tighter than P_s s_a + P_t t_a, whose terms cancel.
    const Interval Z = e.point[2];
    const V3<Interval> Nv = v3(e.normal);
    const Interval Zn = -Z / (Nv.x * a + Nv.y * b + Nv.z);
    const Interval Z_a = Zn * Nv.x, Z_b = Zn * Nv.y;
    const V3<Interval> Pa{Z + a * Z_a, b * Z_a, Z_a}, Pb{a * Z_b, Z + b * Z_b, Z_b};
    const V3<Interval> Na = along(Ns, s_a, Nt, t_a), Nb = along(Ns, s_b, Nt, t_b);
    P = {{e.point[0], Pa.x, Pb.x}, {e.point[1], Pa.y, Pb.y}, {e.point[2], Pa.z, Pb.z}};
    N = {{e.normal[0], Na.x, Nb.x}, {e.normal[1], Na.y, Nb.y}, {e.normal[2], Na.z, Nb.z}};
    return true;
}

double bilinear_error(const IntervalJet& I, double wa, double wb) {
    if (!I.da.is_finite() || !I.db.is_finite()) return std::numeric_limits<double>::infinity();
    const Interval b =
        (Interval(I.da.rad()) * Interval(wa) + Interval(I.db.rad()) * Interval(wb)) * Interval(0.5);
    return b.hi();
}

bool corner_intensity(const ProjectedPatch& pp, const Scene& lighting, const Material& mat,
                      double a, double b, const ParamBox& box, const MarkJacobian& J,
                      ClusterSystem& scratch, RenderStats& st, std::array<Interval, 3>& I) {
    RaySystem sys(pp, a, b, scratch);
    ParamBox hit;
    Interval q;
    if (!newton_hit(pp, a, b, box, sys, J, hit, q, st)) return false;
    ++st.primary_rays;
    const PatchEnclosure e = enclose(pp.forms, hit);
    I = shade<Interval>(lighting, mat, v3(e.point), v3(e.normal), Vec3{});
    return I[0].is_finite() && I[1].is_finite() && I[2].is_finite();
}

std::array<IntervalJet, 3> intensity_jets(const ProjectedPatch& pp, const Scene& lighting,
                                          const Material& mat, const ParamBox& box,
                                          const PatchEnclosure& e, const IMat<2>& A, Interval a,
                                          Interval b) {
    V3<IntervalJet> P, N;
    if (!surface_jets(pp.forms, box, e, A, a, b, P, N)) {
        const IntervalJet any{Interval(0.0, 1.0), Interval::entire(), Interval::entire()};
        return {any, any, any};
    }
    return shade<IntervalJet>(lighting, mat, P, N, Vec3{});
}

SecondOrder second_order(const ProjectedPatch& pp, const Scene& lighting, const Material& mat,
                         const ParamBox& box, const PatchEnclosure& e, const ClusterSystem& sys,
                         const double ca[2], const double cb[2], int levels, bool dither,
                         ClusterSystem& scratch, RenderStats& st) {
    SecondOrder r;
    const Interval a = Interval::hull(ca[0], ca[1]), b = Interval::hull(cb[0], cb[1]);
    const MarkJacobian J = mark_jacobian(sys, box);
    const std::array<IntervalJet, 3> I = intensity_jets(pp, lighting, mat, box, e, J.A, a, b);
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
        if (!corner_intensity(pp, lighting, mat, ca[k & 1], cb[k >> 1], box, J, scratch, st, Ic))
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
