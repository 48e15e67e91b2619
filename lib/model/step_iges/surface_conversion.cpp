// SPDX-License-Identifier: MIT
#include <seamless/model/step_iges/surface_conversion.h>

#include <BndLib_AddSurface.hxx>
#include <Bnd_Box.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <GeomConvert.hxx>
#include <GeomConvert_ApproxSurface.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BezierCurve.hxx>
#include <Geom_BezierSurface.hxx>
#include <Geom_Conic.hxx>
#include <Geom_ConicalSurface.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_Line.hxx>
#include <Geom_OffsetSurface.hxx>
#include <Geom_Plane.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_SphericalSurface.hxx>
#include <Geom_SurfaceOfLinearExtrusion.hxx>
#include <Geom_SurfaceOfRevolution.hxx>
#include <Geom_ToroidalSurface.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <Standard_Failure.hxx>

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

namespace seamless::step_iges {
namespace {

// Curves GeomConvert turns into B-splines exactly: lines, conics, Bezier and
// B-spline curves (trimmed or not).
bool exact_curve(Handle(Geom_Curve) c) {
    while (auto t = Handle(Geom_TrimmedCurve)::DownCast(c)) c = t->BasisCurve();
    return c->IsKind(STANDARD_TYPE(Geom_Line)) || c->IsKind(STANDARD_TYPE(Geom_Conic)) ||
           c->IsKind(STANDARD_TYPE(Geom_BezierCurve)) ||
           c->IsKind(STANDARD_TYPE(Geom_BSplineCurve));
}

// The surface GeomConvert::SurfaceToBSplineSurface converts exactly, or null
// (it would approximate the others silently, to 1e-4).
Handle(Geom_Surface) exact_form(Handle(Geom_Surface) s) {
    while (auto t = Handle(Geom_RectangularTrimmedSurface)::DownCast(s)) s = t->BasisSurface();
    if (auto o = Handle(Geom_OffsetSurface)::DownCast(s)) {
        s = o->Surface(); // the equivalent plane, quadric or torus, when there is one
        if (s.IsNull()) return s;
    }
    if (s->IsKind(STANDARD_TYPE(Geom_ElementarySurface)) ||
        s->IsKind(STANDARD_TYPE(Geom_BezierSurface)) ||
        s->IsKind(STANDARD_TYPE(Geom_BSplineSurface)))
        return s;
    if (auto r = Handle(Geom_SurfaceOfRevolution)::DownCast(s))
        return exact_curve(r->BasisCurve()) ? s : Handle(Geom_Surface)();
    if (auto e = Handle(Geom_SurfaceOfLinearExtrusion)::DownCast(s))
        return exact_curve(e->BasisCurve()) ? s : Handle(Geom_Surface)();
    return Handle(Geom_Surface)();
}

} // namespace

std::string kind_of(const Handle(Geom_Surface) & s) {
    if (s->IsKind(STANDARD_TYPE(Geom_BSplineSurface))) return "B-spline";
    if (s->IsKind(STANDARD_TYPE(Geom_BezierSurface))) return "Bezier";
    if (s->IsKind(STANDARD_TYPE(Geom_Plane))) return "plane";
    if (s->IsKind(STANDARD_TYPE(Geom_CylindricalSurface))) return "cylinder";
    if (s->IsKind(STANDARD_TYPE(Geom_ConicalSurface))) return "cone";
    if (s->IsKind(STANDARD_TYPE(Geom_SphericalSurface))) return "sphere";
    if (s->IsKind(STANDARD_TYPE(Geom_ToroidalSurface))) return "torus";
    if (s->IsKind(STANDARD_TYPE(Geom_SurfaceOfRevolution))) return "surface of revolution";
    if (s->IsKind(STANDARD_TYPE(Geom_SurfaceOfLinearExtrusion))) return "surface of extrusion";
    if (auto o = Handle(Geom_OffsetSurface)::DownCast(s))
        return "offset " + kind_of(o->BasisSurface());
    if (auto t = Handle(Geom_RectangularTrimmedSurface)::DownCast(s))
        return kind_of(t->BasisSurface());
    return s->DynamicType()->Name();
}

Converted convert(const Handle(Geom_Surface) & s, double u1, double u2, double v1, double v2,
                  double rel_tol, double abs_tol) {
    Converted c;
    Handle(Geom_Surface) exact = exact_form(s);
    if (!exact.IsNull()) {
        auto bs = Handle(Geom_BSplineSurface)::DownCast(exact);
        double U1, U2, V1, V2;
        exact->Bounds(U1, U2, V1, V2);
        // A B-spline over (nearly) its own domain is taken as it is.
        const double du = 1e-12 * (U2 - U1), dv = 1e-12 * (V2 - V1);
        if (!bs.IsNull() && std::abs(U1 - u1) <= du && std::abs(U2 - u2) <= du &&
            std::abs(V1 - v1) <= dv && std::abs(V2 - v2) <= dv)
            c.surface = Handle(Geom_BSplineSurface)::DownCast(bs->Copy());
        else
            c.surface = GeomConvert::SurfaceToBSplineSurface(
                new Geom_RectangularTrimmedSurface(exact, u1, u2, v1, v2));
        if (c.surface->IsUPeriodic()) c.surface->SetUNotPeriodic();
        if (c.surface->IsVPeriodic()) c.surface->SetVNotPeriodic();
        if (c.surface->UDegree() <= kMaxDegree && c.surface->VDegree() <= kMaxDegree) return c;
    }
    return approximate(s, u1, u2, v1, v2, rel_tol, abs_tol);
}

Converted approximate(const Handle(Geom_Surface) & s, double u1, double u2, double v1, double v2,
                      double rel_tol, double abs_tol) {
    Converted c;
    Handle(Geom_Surface) part = new Geom_RectangularTrimmedSurface(s, u1, u2, v1, v2);
    Bnd_Box box;
    BndLib_AddSurface::Add(GeomAdaptor_Surface(part), 0.0, box);
    const double tol = std::max(rel_tol * std::sqrt(box.SquareExtent()), abs_tol);
    // OpenCASCADE allocates for the most segments it may use: where 1000
    // fails (NCollection_Array2::Allocate on a degree-13 patch of
    // ksu_c_el_D_D63_L54), fewer are tried.
    for (auto [cont, segments] : {std::pair{GeomAbs_C1, 1000}, std::pair{GeomAbs_C0, 1000},
                                  std::pair{GeomAbs_C1, 100}, std::pair{GeomAbs_C0, 100}}) {
        std::optional<GeomConvert_ApproxSurface> attempt;
        try {
            attempt.emplace(part, tol, cont, cont, kMaxDegree, kMaxDegree, segments, 0);
        } catch (const Standard_Failure&) {
            continue;
        }
        const GeomConvert_ApproxSurface& approx = *attempt;
        if (!approx.HasResult()) continue;
        c.surface = approx.Surface();
        c.exact = false;
        c.error = approx.MaxError();
        if (c.surface->IsUPeriodic()) c.surface->SetUNotPeriodic();
        if (c.surface->IsVPeriodic()) c.surface->SetVNotPeriodic();
        return c;
    }
    c.surface.Nullify();
    return c;
}

BSplineSurface to_model(const Handle(Geom_BSplineSurface) & b, const std::string& name) {
    BSplineSurface s;
    s.name = name;
    s.degree_u = b->UDegree();
    s.degree_v = b->VDegree();
    s.size_u = b->NbUPoles();
    s.size_v = b->NbVPoles();
    TColStd_Array1OfReal ku(1, s.size_u + s.degree_u + 1), kv(1, s.size_v + s.degree_v + 1);
    b->UKnotSequence(ku);
    b->VKnotSequence(kv);
    s.knots_u.assign(ku.begin(), ku.end());
    s.knots_v.assign(kv.begin(), kv.end());
    // The outermost knots never act on the domain; where only they keep a
    // knot vector from being clamped (periodic surfaces made non-periodic),
    // clamp it.
    for (auto [knots, p] : {std::pair{&s.knots_u, s.degree_u}, std::pair{&s.knots_v, s.degree_v}}) {
        std::vector<double>& U = *knots;
        const size_t n = U.size();
        if (U[1] == U[p] && U[p] < U[p + 1]) U.front() = U[p];
        if (U[n - 2] == U[n - 1 - p] && U[n - 2 - p] < U[n - 1 - p]) U.back() = U[n - 1 - p];
    }
    const bool rational = b->IsURational() || b->IsVRational();
    s.points.reserve(static_cast<size_t>(s.size_u) * s.size_v);
    for (int i = 1; i <= s.size_u; ++i)
        for (int j = 1; j <= s.size_v; ++j) {
            const gp_Pnt p = b->Pole(i, j);
            s.points.push_back({p.X(), p.Y(), p.Z()});
            if (rational) s.weights.push_back(b->Weight(i, j));
        }
    return s;
}

} // namespace seamless::step_iges
