// SPDX-License-Identifier: MIT
#include <seamless/base/check.h>
#include <seamless/spline/enclosure/enclosure.h>

#include <algorithm>

namespace seamless {
namespace {

// Parameter box inside [0,1]^2 (what the convex hull bounds need).
bool in_unit_square(ParamBox b) {
    return b.s.lo() >= 0 && b.s.hi() <= 1 && b.t.lo() >= 0 && b.t.hi() <= 1;
}

} // namespace

Interval enclose(const PowerForm& f, const PowerForm& fs, const PowerForm& ft, int c,
                 ParamBox box) {
    const Interval h = horner(f, c, box);
    if (box.s.is_thin() && box.t.is_thin()) return h;
    // Proposition 1: mean value form with the center at the midpoint.
    const double sm = box.s.mid(), tm = box.t.mid();
    const ParamBox center{Interval(sm), Interval(tm)};
    const Interval mvf = horner(f, c, center) + horner(fs, c, box) * (box.s - Interval(sm)) +
                         horner(ft, c, box) * (box.t - Interval(tm));
    return intersect(h, mvf);
}

PatchForms patch_forms(const BezierPatch& b) {
    PatchForms f;
    patch_forms(b, f);
    return f;
}

void patch_forms(const BezierPatch& b, PatchForms& f) {
    power_form(b, f.X);
    derivative_s(f.X, f.Xs);
    derivative_t(f.X, f.Xt);
    derivative_s(f.Xs, f.Xss);
    derivative_t(f.Xs, f.Xst);
    derivative_t(f.Xt, f.Xtt);
    f.rational = b.rational;
    double wlo = b.at(0, 0).w, whi = wlo;
    IVec3 hull3 = IVec3::empty();
    for (int i = 0; i <= b.p; ++i)
        for (int j = 0; j <= b.q; ++j) {
            const HPoint& h = b.at(i, j);
            wlo = std::min(wlo, h.w);
            whi = std::max(whi, h.w);
            for (int k = 0; k < 3; ++k) {
                const Interval x = h.w == 1 ? Interval(h[k]) : Interval(h[k]) / Interval(h.w);
                hull3[k] = hull(hull3[k], x);
            }
        }
    if (!f.rational && (wlo != 1 || whi != 1)) f.rational = true;
    f.w_hull = {wlo, whi};
    f.control_hull = hull3;
}

IVec3 cross(const IVec3& a, const IVec3& b) {
    return IVec3{{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}

IVec3 enclose_point(const PatchForms& f, ParamBox box) {
    SEAMLESS_CHECK(in_unit_square(box), "the convex hull bounds hold over [0,1]^2 only");
    IVec3 P;
    if (!f.rational) {
        for (int c = 0; c < 3; ++c)
            P[c] = intersect(enclose(f.X, f.Xs, f.Xt, c, box), f.control_hull[c]);
        return P;
    }
    // Convex hull property: W over the box lies in [min w_ij, max w_ij] > 0.
    const Interval W = intersect(enclose(f.X, f.Xs, f.Xt, 3, box), f.w_hull);
    const Interval Ws = horner(f.Xs, 3, box), Wt = horner(f.Xt, 3, box);
    IVec3 naive;
    for (int c = 0; c < 3; ++c) naive[c] = enclose(f.X, f.Xs, f.Xt, c, box) / W;
    if (box.s.is_thin() && box.t.is_thin()) {
        for (int c = 0; c < 3; ++c) P[c] = intersect(naive[c], f.control_hull[c]);
        return P;
    }
    // Proposition 1 on P = X / W itself: the quotient of two enclosures is only
    // first order, the mean value form with P_s = (X_s - P W_s) / W is second order.
    const double sm = box.s.mid(), tm = box.t.mid();
    const ParamBox center{Interval(sm), Interval(tm)};
    const Interval Wm = intersect(horner(f.X, 3, center), f.w_hull);
    for (int c = 0; c < 3; ++c) {
        const Interval Pm = horner(f.X, c, center) / Wm;
        const Interval Ps = (horner(f.Xs, c, box) - naive[c] * Ws) / W;
        const Interval Pt = (horner(f.Xt, c, box) - naive[c] * Wt) / W;
        const Interval mvf = Pm + Ps * (box.s - Interval(sm)) + Pt * (box.t - Interval(tm));
        P[c] = intersect(intersect(naive[c], mvf), f.control_hull[c]);
    }
    return P;
}

PatchEnclosure enclose(const PatchForms& f, ParamBox box) {
    return enclose(f, box, enclose_point(f, box));
}

PatchEnclosure enclose(const PatchForms& f, ParamBox box, const IVec3& point) {
    PatchEnclosure e;
    e.point = point;
    IVec3 Xs, Xt;
    for (int c = 0; c < 3; ++c) {
        Xs[c] = enclose(f.Xs, f.Xss, f.Xst, c, box);
        Xt[c] = enclose(f.Xt, f.Xst, f.Xtt, c, box);
    }
    if (!f.rational) {
        e.ds = Xs;
        e.dt = Xt;
    } else {
        // Quotient rule: P_s = (X_s W - X W_s) / W^2 = (X_s - P W_s) / W.
        const Interval W = intersect(enclose(f.X, f.Xs, f.Xt, 3, box), f.w_hull);
        const Interval Ws = enclose(f.Xs, f.Xss, f.Xst, 3, box);
        const Interval Wt = enclose(f.Xt, f.Xst, f.Xtt, 3, box);
        for (int c = 0; c < 3; ++c) {
            e.ds[c] = (Xs[c] - e.point[c] * Ws) / W;
            e.dt[c] = (Xt[c] - e.point[c] * Wt) / W;
        }
    }
    e.normal = cross(e.ds, e.dt);
    return e;
}

PatchSecondDerivatives enclose_second(const PatchForms& f, ParamBox box, const PatchEnclosure& e) {
    PatchSecondDerivatives d;
    for (int c = 0; c < 3; ++c) {
        d.ss[c] = horner(f.Xss, c, box);
        d.st[c] = horner(f.Xst, c, box);
        d.tt[c] = horner(f.Xtt, c, box);
    }
    if (!f.rational) return d;
    const Interval W = intersect(horner(f.X, 3, box), f.w_hull);
    const Interval Ws = horner(f.Xs, 3, box), Wt = horner(f.Xt, 3, box);
    const Interval Wss = horner(f.Xss, 3, box), Wst = horner(f.Xst, 3, box),
                   Wtt = horner(f.Xtt, 3, box);
    const Interval two(2.0);
    for (int c = 0; c < 3; ++c) {
        const Interval P = e.point[c], Ps = e.ds[c], Pt = e.dt[c];
        d.ss[c] = (d.ss[c] - two * Ps * Ws - P * Wss) / W;
        d.st[c] = (d.st[c] - Ps * Wt - Pt * Ws - P * Wst) / W;
        d.tt[c] = (d.tt[c] - two * Pt * Wt - P * Wtt) / W;
    }
    return d;
}

PatchThirdDerivatives enclose_third(const PatchForms& f, ParamBox box, const PatchEnclosure& e,
                                    const PatchSecondDerivatives& d2) {
    PatchThirdDerivatives d;
    for (int c = 0; c < 3; ++c) {
        d.sss[c] = horner_derivative(f.Xss, c, 0, box);
        d.sst[c] = horner_derivative(f.Xss, c, 1, box);
        d.stt[c] = horner_derivative(f.Xtt, c, 0, box);
        d.ttt[c] = horner_derivative(f.Xtt, c, 1, box);
    }
    if (!f.rational) return d;
    const Interval W = intersect(horner(f.X, 3, box), f.w_hull);
    const Interval Ws = horner(f.Xs, 3, box), Wt = horner(f.Xt, 3, box);
    const Interval Wss = horner(f.Xss, 3, box), Wst = horner(f.Xst, 3, box),
                   Wtt = horner(f.Xtt, 3, box);
    const Interval Wsss = horner_derivative(f.Xss, 3, 0, box),
                   Wsst = horner_derivative(f.Xss, 3, 1, box),
                   Wstt = horner_derivative(f.Xtt, 3, 0, box),
                   Wttt = horner_derivative(f.Xtt, 3, 1, box);
    const Interval two(2.0), three(3.0);
    for (int c = 0; c < 3; ++c) {
        const Interval P = e.point[c], Ps = e.ds[c], Pt = e.dt[c];
        const Interval Pss = d2.ss[c], Pst = d2.st[c], Ptt = d2.tt[c];
        d.sss[c] = (d.sss[c] - three * (Pss * Ws) - three * (Ps * Wss) - P * Wsss) / W;
        d.sst[c] =
            (d.sst[c] - Pss * Wt - two * (Pst * Ws) - two * (Ps * Wst) - Pt * Wss - P * Wsst) / W;
        d.stt[c] =
            (d.stt[c] - Ptt * Ws - two * (Pst * Wt) - two * (Pt * Wst) - Ps * Wtt - P * Wstt) / W;
        d.ttt[c] = (d.ttt[c] - three * (Ptt * Wt) - three * (Pt * Wtt) - P * Wttt) / W;
    }
    return d;
}

} // namespace seamless
