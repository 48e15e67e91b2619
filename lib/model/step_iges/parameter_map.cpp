// SPDX-License-Identifier: MIT
#include <seamless/model/step_iges/parameter_map.h>

#include <seamless/model/step_iges/curve_conversion.h>

#include <BSplCLib.hxx>
#include <Geom2dAPI_Interpolate.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_HArray1OfReal.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#include <TColgp_HArray1OfPnt2d.hxx>

#include <algorithm>
#include <cmath>
#include <set>

namespace seamless::step_iges {
namespace {

constexpr int kNewtonSteps = 50;
constexpr double kIdentity = 1e-11; // of the range: the conversion kept the parameter
constexpr double kConverged = 1e-9; // of the diagonal: Newton's method found the point
constexpr int kMaxSamples = 1024;   // intervals per piece of a carried pcurve

// True when every control point has the same coordinate `axis` (0: u, 1: v).
bool constant(const BSplineCurve& c, int axis) {
    for (const Vec3& p : c.points)
        if (p[axis] != c.points[0][axis]) return false;
    return true;
}

// The cubic from p at t0 to q at t1, linear in t.
Handle(Geom2d_BSplineCurve) line(const gp_Pnt2d& p, const gp_Pnt2d& q, double t0, double t1) {
    TColgp_Array1OfPnt2d poles(1, 4);
    for (int i = 0; i < 4; ++i) poles(i + 1) = gp_Pnt2d(p.XY() + (q.XY() - p.XY()) * (i / 3.0));
    TColStd_Array1OfReal knots(1, 2);
    knots(1) = t0, knots(2) = t1;
    TColStd_Array1OfInteger mults(1, 2);
    mults.Init(4);
    return new Geom2d_BSplineCurve(poles, knots, mults, 3);
}

// Appends the clamped cubic `piece`, which starts where `out` ends.
void append(BSplineCurve& out, const BSplineCurve& piece) {
    if (out.points.empty()) {
        out = piece;
        return;
    }
    out.knots.pop_back(); // the joint keeps multiplicity 3: C0
    out.knots.insert(out.knots.end(), piece.knots.begin() + 4, piece.knots.end());
    out.points.insert(out.points.end(), piece.points.begin() + 1, piece.points.end());
}

} // namespace

ParameterMap::ParameterMap(const Handle(Geom_Surface) & file_surface,
                           const BSplineSurface& converted, double u1, double u2, double v1,
                           double v2)
    : file_(file_surface), conv_(converted), u1_(u1), u2_(u2), v1_(v1), v2_(v2) {
    bool same_u = conv_.u_min() == u1 && conv_.u_max() == u2;
    bool same_v = conv_.v_min() == v1 && conv_.v_max() == v2;
    // Fractions away from the symmetric points of arcs, where the rational
    // circle's parameter agrees with the angle; on the lines u() and v() use.
    const Box3 box = control_box(conv_);
    const double tol = kConverged * distance(box.lo, box.hi);
    for (double a : {0.13, 0.37, 0.58, 0.81, 0.94}) {
        const double fu = u1 + (u2 - u1) * a, fv = v2 - (v2 - v1) * a;
        double cu = 0, cv = 0;
        valid_ = valid_ && invert(fu, 0.5 * (v1 + v2), cu, cv) <= tol;
        same_u = same_u && std::abs(cu - fu) <= kIdentity * (u2 - u1);
        valid_ = valid_ && invert(0.5 * (u1 + u2), fv, cu, cv) <= tol;
        same_v = same_v && std::abs(cv - fv) <= kIdentity * (v2 - v1);
    }
    identity_u_ = same_u;
    identity_v_ = same_v;
    if (!valid_) return;
    if (!identity_u_) images_u_ = knot_images(0);
    if (!identity_v_) images_v_ = knot_images(1);
}

double ParameterMap::invert(double fu, double fv, double& cu, double& cv) const {
    const gp_Pnt t = file_->Value(fu, fv);
    const Vec3 target{t.X(), t.Y(), t.Z()};
    const double U1 = conv_.u_min(), U2 = conv_.u_max(), V1 = conv_.v_min(), V2 = conv_.v_max();
    cu = U1 + (fu - u1_) / (u2_ - u1_) * (U2 - U1);
    cv = V1 + (fv - v1_) / (v2_ - v1_) * (V2 - V1);
    for (int step = 0; step < kNewtonSteps; ++step) {
        const SurfacePoint s = evaluate(conv_, cu, cv);
        const Vec3 r = target - s.point;
        const double a = dot(s.du, s.du), b = dot(s.du, s.dv), c = dot(s.dv, s.dv);
        const double ru = dot(s.du, r), rv = dot(s.dv, r);
        const double det = a * c - b * b;
        double du = 0, dv = 0;
        if (det > 1e-24 * a * c) {
            du = (c * ru - b * rv) / det;
            dv = (a * rv - b * ru) / det;
        } else if (a > c) { // a pole or apex line: only u moves the point
            du = ru / a;
        } else if (c > 0) {
            dv = rv / c;
        }
        const double nu = std::clamp(cu + du, U1, U2), nv = std::clamp(cv + dv, V1, V2);
        // Quadratic convergence: the step after one this small is rounding.
        const bool done =
            std::abs(nu - cu) <= 1e-13 * (U2 - U1) && std::abs(nv - cv) <= 1e-13 * (V2 - V1);
        cu = nu, cv = nv;
        if (done) break;
    }
    return distance(evaluate(conv_, cu, cv).point, target);
}

double ParameterMap::u(double file_u) const {
    if (identity_u_) return file_u;
    double cu, cv;
    invert(file_u, 0.5 * (v1_ + v2_), cu, cv);
    return cu;
}

double ParameterMap::v(double file_v) const {
    if (identity_v_) return file_v;
    double cu, cv;
    invert(0.5 * (u1_ + u2_), file_v, cu, cv);
    return cv;
}

std::vector<double> ParameterMap::knot_images(int axis) const {
    const std::vector<double>& knots = axis == 0 ? conv_.knots_u : conv_.knots_v;
    const double lo = axis == 0 ? u1_ : v1_, hi = axis == 0 ? u2_ : v2_;
    const double first = axis == 0 ? conv_.u_min() : conv_.v_min();
    const double last = axis == 0 ? conv_.u_max() : conv_.v_max();
    std::vector<double> images;
    for (double k : std::set<double>(knots.begin(), knots.end())) {
        if (k <= first || k >= last) continue;
        double a = lo, b = hi; // the map is increasing: bisect for its preimage of k
        for (int step = 0; step < 60; ++step) {
            const double m = 0.5 * (a + b);
            ((axis == 0 ? u(m) : v(m)) < k ? a : b) = m;
        }
        images.push_back(0.5 * (a + b));
    }
    return images;
}

// Parameters in (t0, t1) where the pcurve has a knot or crosses a knot
// line of the converted surface: the carried pcurve may have a kink there.
std::vector<double> ParameterMap::breaks(const BSplineCurve& pc, double t0, double t1) const {
    std::vector<double> t{t0, t1};
    for (double k : pc.knots)
        if (t0 < k && k < t1) t.push_back(k);
    for (int axis : {0, 1}) {
        if (axis == 0 ? identity_u_ : identity_v_) continue;
        for (double image : axis == 0 ? images_u_ : images_v_) {
            const auto f = [&](double s) { return evaluate(pc, s).point[axis] - image; };
            constexpr int kScan = 64;
            for (int i = 0; i < kScan; ++i) {
                double a = t0 + (t1 - t0) * i / kScan, b = t0 + (t1 - t0) * (i + 1) / kScan;
                if ((f(a) < 0) == (f(b) < 0)) continue;
                const bool rising = f(a) < 0;
                for (int step = 0; step < 60; ++step) {
                    const double m = 0.5 * (a + b);
                    ((f(m) < 0) == rising ? a : b) = m;
                }
                t.push_back(0.5 * (a + b));
            }
        }
    }
    std::sort(t.begin(), t.end());
    std::vector<double> out;
    for (double x : t)
        if (out.empty() || x - out.back() > 1e-12 * (t1 - t0)) out.push_back(x);
    out.back() = t1;
    return out;
}

BSplineCurve ParameterMap::carry(const BSplineCurve& pc, double t0, double t1, double uv_tol,
                                 double& error) const {
    error = 0;
    const bool fixed_u = identity_u_ || constant(pc, 0);
    const bool fixed_v = identity_v_ || constant(pc, 1);
    if (fixed_u && fixed_v) { // an iso-line: its constant coordinate maps exactly
        BSplineCurve c = pc;
        const double cu = u(pc.points[0].x), cv = v(pc.points[0].y);
        for (Vec3& p : c.points) p = {identity_u_ ? p.x : cu, identity_v_ ? p.y : cv, 0};
        return c;
    }
    const auto mapped = [&](double t) {
        const Vec3 p = evaluate(pc, t).point;
        return gp_Pnt2d(u(p.x), v(p.y));
    };
    // Cubic interpolation between the breaks, halving the step until the
    // midpoints are within the tolerance; the pieces joined with C0 knots.
    const std::vector<double> b = breaks(pc, t0, t1);
    BSplineCurve out;
    out.degree = 3;
    for (size_t k = 0; k + 1 < b.size(); ++k) {
        Handle(Geom2d_BSplineCurve) piece;
        double worst = 0;
        // The samples of each round are the last round's and its check
        // points (the midpoints), mapped once.
        std::vector<double> ts, mids;
        std::vector<gp_Pnt2d> at, at_mids;
        for (int i = 0; i <= 4; ++i) {
            ts.push_back(i == 4 ? b[k + 1] : b[k] + (b[k + 1] - b[k]) * i / 4);
            at.push_back(mapped(ts.back()));
        }
        for (;;) {
            const int n = static_cast<int>(ts.size()) - 1;
            Handle(TColgp_HArray1OfPnt2d) points = new TColgp_HArray1OfPnt2d(1, n + 1);
            Handle(TColStd_HArray1OfReal) params = new TColStd_HArray1OfReal(1, n + 1);
            for (int i = 0; i <= n; ++i) {
                params->SetValue(i + 1, ts[i]);
                points->SetValue(i + 1, at[i]);
            }
            try {
                Geom2dAPI_Interpolate interpolate(points, params, Standard_False, 1e-15);
                interpolate.Perform();
                if (!interpolate.IsDone()) return {};
                piece = interpolate.Curve();
            } catch (const Standard_Failure&) { // points too close to tell apart: a line
                piece = line(points->Value(1), points->Value(n + 1), b[k], b[k + 1]);
            }
            worst = 0;
            mids.clear();
            at_mids.clear();
            for (int i = 0; i < n; ++i) {
                mids.push_back(0.5 * (ts[i] + ts[i + 1]));
                at_mids.push_back(mapped(mids.back()));
                worst = std::max(worst, piece->Value(mids.back()).Distance(at_mids.back()));
            }
            if (worst <= uv_tol || 2 * n > kMaxSamples) break;
            std::vector<double> ts2{ts[0]};
            std::vector<gp_Pnt2d> at2{at[0]};
            for (int i = 0; i < n; ++i) {
                ts2.insert(ts2.end(), {mids[i], ts[i + 1]});
                at2.insert(at2.end(), {at_mids[i], at[i + 1]});
            }
            ts = std::move(ts2);
            at = std::move(at2);
        }
        error = std::max(error, worst);
        const ConvertedCurve c = convert_pcurve(piece, b[k], b[k + 1], uv_tol);
        if (!c.ok || c.curve.degree != 3) return {};
        append(out, c.curve);
    }
    return out;
}

} // namespace seamless::step_iges
