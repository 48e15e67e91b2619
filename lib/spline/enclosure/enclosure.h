// SPDX-License-Identifier: MIT
// Range enclosures of a Bezier patch over a parameter box [s] x [t] in [0,1]^2
// (paper section 5): the point P, the partial derivatives dP/ds, dP/dt and the
// normal dP/ds x dP/dt. Each coordinate is the intersection of
//  - Horner on the power form (polynomial_range.h), ordered as sum_i b_i(t) s^i when [t] is the
//    narrower interval and sum_j c_j(s) t^j otherwise, each one-dimensional
//    polynomial with interval coefficients bounded by Lemma 2 (parameters >= 0);
//  - the mean value form f(mid) + f_s(box)(s - mid s) + f_t(box)(t - mid t)
//    (Proposition 1), whose overestimation is O(rad^2);
//  - the hull of the control points (convex hull property, section 4).
// Rational patches: the homogeneous X and W are enclosed, W is intersected with
// [min w_ij, max w_ij] (keeps W > 0), P = X / W, derivatives by the quotient
// rule P_s = (X_s - P W_s) / W. All with outward rounding: enclosures never miss.
#pragma once

#include <seamless/interval/interval.h>
#include <seamless/interval/interval_matrix.h>
#include <seamless/spline/bezier_patch.h>
#include <seamless/spline/enclosure/polynomial_range.h>
#include <seamless/spline/enclosure/power_form.h>

namespace seamless {

using IVec3 = IVec<3>;

// Everything the enclosures need, computed once per patch (6.4 KB up to
// bicubic forms, which are inside; higher degrees on the heap: power_form.h).
struct PatchForms {
    PowerForm X, Xs, Xt, Xss, Xst, Xtt; // homogeneous coordinates and their derivatives
    bool rational = false;
    Interval w_hull{1.0}; // [min w_ij, max w_ij]: W over [0,1]^2 (convex hull property)
    IVec3 control_hull;   // hull of the projected control points, outward rounded
};
PatchForms patch_forms(const BezierPatch& b);
// The same into f (in place: no temporary copy of the set).
void patch_forms(const BezierPatch& b, PatchForms& f);

struct PatchEnclosure {
    IVec3 point, ds, dt, normal; // over the box; derivatives in local (s, t)
};

// Horner intersected with the mean value form; fs, ft: the power forms of f_s, f_t.
Interval enclose(const PowerForm& f, const PowerForm& fs, const PowerForm& ft, int c, ParamBox box);

IVec3 enclose_point(const PatchForms& f, ParamBox box);
PatchEnclosure enclose(const PatchForms& f, ParamBox box);
// The same with point = enclose_point(f, box) already known (the same result).
PatchEnclosure enclose(const PatchForms& f, ParamBox box, const IVec3& point);

// The second partial derivatives of the point over a box: P_ss, P_st, P_tt
// (Horner on the power forms; rational patches by differentiating X = P W twice:
// X_ss = P_ss W + 2 P_s W_s + P W_ss, X_st = P_st W + P_s W_t + P_t W_s + P W_st).
// e: enclose(f, box), whose point and first derivatives the quotient rule reuses.
struct PatchSecondDerivatives {
    IVec3 ss, st, tt;
};
PatchSecondDerivatives enclose_second(const PatchForms& f, ParamBox box, const PatchEnclosure& e);

// The third partial derivatives of the point over a box: P_sss, P_sst, P_stt,
// P_ttt (Horner on the differentiated coefficients of X_ss and X_tt, no power
// form built; rational patches by differentiating X = P W three times, Leibniz:
// X_sss = P_sss W + 3 P_ss W_s + 3 P_s W_ss + P W_sss,
// X_sst = P_sst W + P_ss W_t + 2 P_st W_s + 2 P_s W_st + P_t W_ss + P W_sst).
// e, d2: enclose(f, box) and enclose_second(f, box, e).
struct PatchThirdDerivatives {
    IVec3 sss, sst, stt, ttt;
};
PatchThirdDerivatives enclose_third(const PatchForms& f, ParamBox box, const PatchEnclosure& e,
                                    const PatchSecondDerivatives& d2);

// Cross product of interval vectors (the normal of section 5).
IVec3 cross(const IVec3& a, const IVec3& b);

} // namespace seamless
