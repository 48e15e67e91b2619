// SPDX-License-Identifier: MIT
#include <seamless/model/step_iges/curve_conversion.h>

#include <Geom2dConvert.hxx>
#include <Geom2dConvert_ApproxCurve.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Geom2d_BezierCurve.hxx>
#include <Geom2d_Line.hxx>
#include <Geom2d_TrimmedCurve.hxx>
#include <GeomConvert.hxx>
#include <GeomConvert_ApproxCurve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BezierCurve.hxx>
#include <Geom_Line.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <TColStd_Array1OfReal.hxx>

#include <cmath>

namespace seamless::step_iges {
namespace {

// OpenCASCADE's 3D and 2D curve families, for one conversion written once.
struct Space3 {
    using Curve = Geom_Curve;
    using BSpline = Geom_BSplineCurve;
    using Bezier = Geom_BezierCurve;
    using Line = Geom_Line;
    using Trimmed = Geom_TrimmedCurve;
    using Approx = GeomConvert_ApproxCurve;
    using Poles = TColgp_Array1OfPnt;
    static Handle(BSpline) to_bspline(const Handle(Curve) & c) {
        return GeomConvert::CurveToBSplineCurve(c);
    }
    static Vec3 vec(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }
};

struct Space2 {
    using Curve = Geom2d_Curve;
    using BSpline = Geom2d_BSplineCurve;
    using Bezier = Geom2d_BezierCurve;
    using Line = Geom2d_Line;
    using Trimmed = Geom2d_TrimmedCurve;
    using Approx = Geom2dConvert_ApproxCurve;
    using Poles = TColgp_Array1OfPnt2d;
    static Handle(BSpline) to_bspline(const Handle(Curve) & c) {
        return Geom2dConvert::CurveToBSplineCurve(c);
    }
    static Vec3 vec(const gp_Pnt2d& p) { return {p.X(), p.Y(), 0}; }
};

template <class S> BSplineCurve to_model(const Handle(typename S::BSpline) & b) {
    BSplineCurve c;
    c.degree = b->Degree();
    const int n = b->NbPoles();
    TColStd_Array1OfReal knots(1, n + c.degree + 1);
    b->KnotSequence(knots);
    c.knots.assign(knots.begin(), knots.end());
    // As for surfaces (surface_conversion.cpp): the outermost knots never act
    // on the domain; clamp them where only they keep the vector unclamped.
    std::vector<double>& U = c.knots;
    const int p = c.degree;
    const size_t m = U.size();
    if (U[1] == U[p] && U[p] < U[p + 1]) U.front() = U[p];
    if (U[m - 2] == U[m - 1 - p] && U[m - 2 - p] < U[m - 1 - p]) U.back() = U[m - 1 - p];
    c.points.reserve(n);
    for (int i = 1; i <= n; ++i) {
        c.points.push_back(S::vec(b->Pole(i)));
        if (b->IsRational()) c.weights.push_back(b->Weight(i));
    }
    return c;
}

// A B-spline over [f, l] with the curve's own parameter, or null.
template <class S>
Handle(typename S::BSpline) exact_bspline(Handle(typename S::Curve) c, double f, double l) {
    while (auto t = Handle(typename S::Trimmed)::DownCast(c)) c = t->BasisCurve();
    Handle(typename S::BSpline) b;
    if (auto bs = Handle(typename S::BSpline)::DownCast(c)) {
        b = Handle(typename S::BSpline)::DownCast(bs->Copy());
    } else if (Handle(typename S::Bezier)::DownCast(c)) {
        b = S::to_bspline(c); // knots [0, 1]: the Bezier parameter
    } else if (Handle(typename S::Line)::DownCast(c)) {
        typename S::Poles poles(1, 2);
        poles(1) = c->Value(f);
        poles(2) = c->Value(l);
        TColStd_Array1OfReal knots(1, 2);
        knots(1) = f, knots(2) = l;
        TColStd_Array1OfInteger mults(1, 2);
        mults.Init(2);
        return new typename S::BSpline(poles, knots, mults, 1);
    } else {
        return b;
    }
    if (b->IsPeriodic()) {
        // [f, l] may run past the first period: cut the curve there (exact).
        if (f < b->FirstParameter() || l > b->LastParameter()) b->Segment(f, l);
        if (b->IsPeriodic()) b->SetNotPeriodic();
    }
    return b;
}

template <class S>
ConvertedCurve convert(const Handle(typename S::Curve) & c, double f, double l, double tol) {
    ConvertedCurve r;
    Handle(typename S::BSpline) b = exact_bspline<S>(c, f, l);
    if (!b.IsNull() && b->Degree() <= kMaxDegree && b->FirstParameter() <= f &&
        l <= b->LastParameter()) {
        r.curve = to_model<S>(b);
        r.ok = true;
        return r;
    }
    // Approximating t -> c(t) keeps the parameter.
    const Handle(typename S::Curve) part = new typename S::Trimmed(c, f, l);
    for (GeomAbs_Shape cont : {GeomAbs_C2, GeomAbs_C1, GeomAbs_C0}) {
        typename S::Approx approx(part, tol, cont, 1000, kMaxDegree);
        if (!approx.HasResult()) continue;
        r.curve = to_model<S>(approx.Curve());
        // A trimmed periodic curve moves [f, l] into its first period: the
        // same points, a whole number of periods earlier.
        const double shift = f - r.curve.t_min();
        for (double& k : r.curve.knots) k += shift;
        r.ok = true;
        r.error = approx.MaxError();
        return r;
    }
    return r;
}

} // namespace

ConvertedCurve convert_curve(const Handle(Geom_Curve) & c, double f, double l, double tol) {
    return convert<Space3>(c, f, l, tol);
}

ConvertedCurve convert_pcurve(const Handle(Geom2d_Curve) & c, double f, double l, double tol) {
    return convert<Space2>(c, f, l, tol);
}

} // namespace seamless::step_iges
