// SPDX-License-Identifier: MIT
#include <seamless/model/step_iges/face_range.h>

#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Geom2d_Curve.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <Precision.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>

#include <algorithm>
#include <cmath>

namespace seamless::step_iges {

FaceRange face_range(const TopoDS_Face& face, const Handle(Geom_Surface) & s) {
    FaceRange r{};
    BRepTools::UVBounds(face, r.u1, r.u2, r.v1, r.v2);
    double U1, U2, V1, V2;
    s->Bounds(U1, U2, V1, V2);
    const bool bounded_u =
        !s->IsUPeriodic() && !Precision::IsInfinite(U1) && !Precision::IsInfinite(U2);
    const bool bounded_v =
        !s->IsVPeriodic() && !Precision::IsInfinite(V1) && !Precision::IsInfinite(V2);
    double tol3 = Precision::Confusion();
    for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next())
        tol3 = std::max(tol3, BRep_Tool::Tolerance(TopoDS::Edge(e.Current())));
    GeomAdaptor_Surface adaptor(s);
    const double tu = std::max(adaptor.UResolution(2 * tol3), 1e-9 * std::abs(r.u2 - r.u1));
    const double tv = std::max(adaptor.VResolution(2 * tol3), 1e-9 * std::abs(r.v2 - r.v1));
    int wires = 0;
    for (TopExp_Explorer w(face, TopAbs_WIRE); w.More(); w.Next()) ++wires;
    r.natural = wires == 1;
    for (TopExp_Explorer e(face, TopAbs_EDGE); e.More() && r.natural; e.Next()) {
        double f, l;
        Handle(Geom2d_Curve) pc = BRep_Tool::CurveOnSurface(TopoDS::Edge(e.Current()), face, f, l);
        if (pc.IsNull()) {
            r.natural = false;
            break;
        }
        for (int k = 0; k <= 8; ++k) {
            const gp_Pnt2d p = pc->Value(f + (l - f) * k / 8);
            const bool on_u_side = std::min(std::abs(p.X() - r.u1), std::abs(p.X() - r.u2)) <= tu;
            const bool on_v_side = std::min(std::abs(p.Y() - r.v1), std::abs(p.Y() - r.v2)) <= tv;
            if (!on_u_side && !on_v_side) r.natural = false;
        }
    }
    if (bounded_u) {
        if (std::abs(r.u1 - U1) > tu || std::abs(r.u2 - U2) > tu) r.natural = false;
        r.u1 = U1, r.u2 = U2;
    }
    if (bounded_v) {
        if (std::abs(r.v1 - V1) > tv || std::abs(r.v2 - V2) > tv) r.natural = false;
        r.v1 = V1, r.v2 = V2;
    }
    return r;
}

} // namespace seamless::step_iges
