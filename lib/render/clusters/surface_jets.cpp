// SPDX-License-Identifier: MIT
#include <seamless/render/clusters/surface_jets.h>

namespace seamless {
namespace {

// A function F over the box and its partials along s and t up to second order.
struct Partials2 {
    Interval F, Fs, Ft, Fss, Fst, Ftt;
};

// F(s(a, b), t(a, b)) from F and its partials along s and t over the box
// (chain rule to second order).
IntervalJet2 compose(const Partials2& p, const IntervalJet2& s, const IntervalJet2& t) {
    const Interval F = p.F, Fs = p.Fs, Ft = p.Ft, Fss = p.Fss, Fst = p.Fst, Ftt = p.Ftt;
    const Interval two(2.0);
    return {
        F,
        Fs * s.da + Ft * t.da,
        Fs * s.db + Ft * t.db,
        Fss * sqr(s.da) + two * (Fst * (s.da * t.da)) + Ftt * sqr(t.da) + Fs * s.daa + Ft * t.daa,
        Fss * (s.da * s.db) + Fst * (s.da * t.db + s.db * t.da) + Ftt * (t.da * t.db) + Fs * s.dab +
            Ft * t.dab,
        Fss * sqr(s.db) + two * (Fst * (s.db * t.db)) + Ftt * sqr(t.db) + Fs * s.dbb + Ft * t.dbb};
}

template <class T> V3<T> cross3(const V3<T>& u, const V3<T>& w) {
    return {u.y * w.z - u.z * w.y, u.z * w.x - u.x * w.z, u.x * w.y - u.y * w.x};
}

} // namespace

bool surface_jets(const CertifiedCluster& c, const IMat<2>& A, Interval a, Interval b,
                  V3<IntervalJet2>& P, V3<IntervalJet2>& N) {
    const PatchForms& f = c.pp.forms;
    const ClusterSystem& sys = c.sys;
    const ParamBox& box = c.box;
    const PatchEnclosure& e = c.e;
    const Interval det = A(0, 0) * A(1, 1) - A(0, 1) * A(1, 0);
    if (det.contains(0.0)) return false;
    // First partials of (s, t): A^-1 (Z, 0) and A^-1 (0, Z), Z = X_2 (times W).
    const Interval Zd = horner(f.X, 2, box) / det;
    const Interval s_a = A(1, 1) * Zd, t_a = -(A(1, 0) * Zd);
    const Interval s_b = -(A(0, 1) * Zd), t_b = A(0, 0) * Zd;
    // Second partials: A (s_xy, t_xy) = -R_xy (the header's formula).
    const Interval Zs = horner(f.Xs, 2, box), Zt = horner(f.Xt, 2, box);
    const Interval two(2.0);
    // The homogeneous Z's partials along a and b through s and t.
    const Interval Zh_a = Zs * s_a + Zt * t_a, Zh_b = Zs * s_b + Zt * t_b;
    Interval Raa[2], Rab[2], Rbb[2];
    for (int k = 0; k < 2; ++k) {
        const Interval Gss = horner_derivative(sys.Gs, k, 0, box);
        const Interval Gst = horner_derivative(sys.Gs, k, 1, box);
        const Interval Gtt = horner_derivative(sys.Gt, k, 1, box);
        Raa[k] = Gss * sqr(s_a) + two * (Gst * (s_a * t_a)) + Gtt * sqr(t_a);
        Rab[k] = Gss * (s_a * s_b) + Gst * (s_a * t_b + s_b * t_a) + Gtt * (t_a * t_b);
        Rbb[k] = Gss * sqr(s_b) + two * (Gst * (s_b * t_b)) + Gtt * sqr(t_b);
    }
    Raa[0] = Raa[0] - two * Zh_a;
    Rab[0] = Rab[0] - Zh_b;
    Rab[1] = Rab[1] - Zh_a;
    Rbb[1] = Rbb[1] - two * Zh_b;
    // (x, y) = -A^-1 R = (A01 R1 - A11 R0, A10 R0 - A00 R1) / det.
    const auto solve_s = [&](const Interval R[2]) {
        return (A(0, 1) * R[1] - A(1, 1) * R[0]) / det;
    };
    const auto solve_t = [&](const Interval R[2]) {
        return (A(1, 0) * R[0] - A(0, 0) * R[1]) / det;
    };
    const IntervalJet2 s{box.s, s_a, s_b, solve_s(Raa), solve_s(Rab), solve_s(Rbb)};
    const IntervalJet2 t{box.t, t_a, t_b, solve_t(Raa), solve_t(Rab), solve_t(Rbb)};
    // N = P_s x P_t with P_s, P_t composed with (s, t).
    const PatchSecondDerivatives d2 = enclose_second(f, box, e);
    const PatchThirdDerivatives d3 = enclose_third(f, box, e, d2);
    V3<IntervalJet2> Ps, Pt;
    IntervalJet2* ps[3] = {&Ps.x, &Ps.y, &Ps.z};
    IntervalJet2* pt[3] = {&Pt.x, &Pt.y, &Pt.z};
    for (int c = 0; c < 3; ++c) {
        *ps[c] = compose({e.ds[c], d2.ss[c], d2.st[c], d3.sss[c], d3.sst[c], d3.stt[c]}, s, t);
        *pt[c] = compose({e.dt[c], d2.st[c], d2.tt[c], d3.sst[c], d3.stt[c], d3.ttt[c]}, s, t);
    }
    N = cross3(Ps, Pt);
    N.x.v = intersect(N.x.v, e.normal[0]);
    N.y.v = intersect(N.y.v, e.normal[1]);
    N.z.v = intersect(N.z.v, e.normal[2]);
    // The depth along the ray: Z_a, Z_b, then their partials as first-order jets.
    const Interval Z = e.point[2];
    const Interval nd = e.normal[0] * a + e.normal[1] * b + e.normal[2];
    const Interval Zn = -Z / nd;
    const Interval Z_a = Zn * e.normal[0], Z_b = Zn * e.normal[1];
    const IntervalJet Z1{Z, Z_a, Z_b};
    const V3<IntervalJet> N1{N.x.first(), N.y.first(), N.z.first()};
    const IntervalJet nd1 = N1.x * IntervalJet{a, Interval(1.0), Interval(0.0)} +
                            N1.y * IntervalJet{b, Interval(0.0), Interval(1.0)} + N1.z;
    const IntervalJet Za1 = -(Z1 * N1.x) / nd1, Zb1 = -(Z1 * N1.y) / nd1;
    const IntervalJet2 Z2{Z,      intersect(Z_a, Za1.v),     intersect(Z_b, Zb1.v),
                          Za1.da, intersect(Za1.db, Zb1.da), Zb1.db};
    P = {Z2 * IntervalJet2{a, Interval(1.0), Interval(0.0), Interval(0.0), Interval(0.0),
                           Interval(0.0)},
         Z2 * IntervalJet2{b, Interval(0.0), Interval(1.0), Interval(0.0), Interval(0.0),
                           Interval(0.0)},
         Z2};
    P.x.v = intersect(P.x.v, e.point[0]);
    P.y.v = intersect(P.y.v, e.point[1]);
    return true;
}

} // namespace seamless
