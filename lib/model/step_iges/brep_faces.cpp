// SPDX-License-Identifier: MIT
#include <seamless/model/step_iges/brep_faces.h>

#include <seamless/base/check.h>
#include <seamless/base/error.h>
#include <seamless/model/step_iges/curve_conversion.h>
#include <seamless/model/step_iges/face_range.h>
#include <seamless/model/step_iges/messages.h>
#include <seamless/model/step_iges/parameter_map.h>
#include <seamless/model/step_iges/surface_conversion.h>

#include <BRepLib.hxx>
#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <Geom_ElementarySurface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_SurfaceOfRevolution.hxx>
#include <Precision.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <utility>

namespace seamless::step_iges {
namespace {

// Curves without an exact B-spline form of degree <= kMaxDegree (rare after
// the conversion) are approximated within this fraction of their edge's
// tolerance.
constexpr double kApproximationFraction = 0.1;

// Maps the curve's knots affinely so that [f, l] becomes [t0, t1].
void reparametrise(BSplineCurve& c, double f, double l, double t0, double t1) {
    const double scale = (t1 - t0) / (l - f);
    for (double& k : c.knots) k = t0 + (k - f) * scale;
}

class FaceReader {
  public:
    FaceReader(const FaceContext& ctx, Model& m)
        : ctx_(ctx), m_(m), edge_read_(ctx.edges.Extent(), false) {
        m_.brep.vertices.resize(ctx.vertices.Extent());
        for (int k = 1; k <= ctx.vertices.Extent(); ++k) {
            const TopoDS_Vertex v = TopoDS::Vertex(ctx.vertices(k));
            const gp_Pnt p = BRep_Tool::Pnt(v);
            m_.brep.vertices[k - 1] = {{p.X(), p.Y(), p.Z()}, BRep_Tool::Tolerance(v)};
        }
        m_.brep.edges.resize(ctx.edges.Extent());
    }

    void read(int k) {
        const TopoDS_Face face = TopoDS::Face(ctx_.faces(k));
        const std::string& name = ctx_.names[k - 1];
        name_ = &name;
        surface(face, name);
        BRepFace f;
        f.surface = static_cast<int>(m_.surfaces.size()) - 1;
        f.reversed = face.Orientation() == TopAbs_REVERSED;
        f.name = name;
        // Loops as they run on the forward face: the face on their left in
        // (u, v), outer loop counterclockwise; `reversed` says the outside.
        const TopoDS_Face fwd = TopoDS::Face(face.Oriented(TopAbs_FORWARD));
        const TopoDS_Wire outer = BRepTools::OuterWire(fwd);
        if (!outer.IsNull()) f.loops.push_back(loop(outer, fwd));
        for (TopoDS_Iterator it(fwd); it.More(); it.Next())
            if (it.Value().ShapeType() == TopAbs_WIRE && !it.Value().IsSame(outer))
                f.loops.push_back(loop(TopoDS::Wire(it.Value()), fwd));
        if (f.loops.empty()) throw InputError(ctx_.file, name, "face without a boundary");
        m_.brep.faces.push_back(std::move(f));
        map_.reset();
    }

    void finish() {
        if (!unordered_.empty())
            m_.warnings.push_back(ctx_.file + ": " + count_of(unordered_.size(), "loop") +
                                  " whose edges OpenCASCADE could not chain, kept in the "
                                  "file's order: " +
                                  list_names(unordered_));
    }

  private:
    // A face all around a periodic u whose seam is not at u = 0: OpenCASCADE
    // converts such a range only as the whole period from 0 (its periodic
    // form), so the surface is turned about its axis to bring the seam
    // there, and r moved to [0, period]: ParameterMap relates the two.
    static Handle(Geom_Surface) seam_at_zero(const Handle(Geom_Surface) & s, FaceRange& r) {
        // GeomConvert takes a range within Precision::PConfusion() of the
        // period for the whole period, from 0.
        if (!s->IsUPeriodic() || r.u1 == 0 || r.u2 - r.u1 < s->UPeriod() - 1e-9) return s;
        gp_Ax1 axis;
        double turn = r.u1;
        if (auto e = Handle(Geom_ElementarySurface)::DownCast(s)) {
            axis = e->Axis();
            if (!e->Position().Direct()) turn = -turn;
        } else if (auto rev = Handle(Geom_SurfaceOfRevolution)::DownCast(s)) {
            axis = rev->Axis();
        } else {
            return s;
        }
        Handle(Geom_Surface) turned = Handle(Geom_Surface)::DownCast(s->Copy());
        turned->Rotate(axis, turn);
        r.u2 = s->UPeriod(), r.u1 = 0;
        return turned;
    }

    // The face's surface in its exact NURBS form (approximated where it has
    // none) over the face's parameter range, as in the untrimmed reader,
    // and how that form moved the face's parameters.
    void surface(const TopoDS_Face& face, const std::string& name) {
        Handle(Geom_Surface) s = BRep_Tool::Surface(face); // located
        if (s.IsNull()) throw InputError(ctx_.file, name, "face without a surface");
        // A trimmed surface has its basis's parameters; the basis says
        // whether they are periodic.
        while (auto t = Handle(Geom_RectangularTrimmedSurface)::DownCast(s)) s = t->BasisSurface();
        FaceRange r = face_range(face, s);
        if (s->IsUPeriodic()) r.u2 = std::min(r.u2, r.u1 + s->UPeriod());
        if (s->IsVPeriodic()) r.v2 = std::min(r.v2, r.v1 + s->VPeriod());
        if (!(r.u1 < r.u2 && r.v1 < r.v2))
            throw InputError(ctx_.file, name, "face with an empty parameter range");
        // A face is no more precise than its tolerance: approximations
        // (rare) need not be either.
        const double face_tol = BRep_Tool::Tolerance(face);
        const double rel_tol = ctx_.options.approximation_tolerance;
        const double abs_tol = kApproximationFraction * face_tol;
        range_ = r;
        period_[0] = s->IsUPeriodic() ? s->UPeriod() : 0;
        period_[1] = s->IsVPeriodic() ? s->VPeriod() : 0;
        // The exact form: with the seam turned to 0 where that applies, else
        // (or where Newton's method cannot relate that one to the file's
        // parameters) over the file's range.
        Converted c;
        for (bool turn : {true, false}) {
            FaceRange range = r;
            const Handle(Geom_Surface) to_convert = turn ? seam_at_zero(s, range) : s;
            if (turn && to_convert == s) continue;
            map_.reset();
            try {
                c = convert(to_convert, range.u1, range.u2, range.v1, range.v2, rel_tol, abs_tol);
            } catch (const Standard_Failure&) { // approximated below, in the file's parameters
                c = Converted{};
                continue;
            }
            if (c.surface.IsNull()) continue;
            map_.emplace(s, to_model(c.surface, name), r.u1, r.u2, r.v1, r.v2);
            if (map_->valid()) break;
        }
        // Where the conversion failed or Newton's method could not relate its
        // parameters to the file's: approximated in the file's parameters,
        // where the pcurves stay as they are.
        if (!map_ || !map_->valid()) {
            map_.reset(); // the file's parameters: the pcurves as they are
            c = approximate(s, r.u1, r.u2, r.v1, r.v2, rel_tol, abs_tol);
        }
        if (c.surface.IsNull())
            throw InputError(ctx_.file, name,
                             "cannot convert its " + kind_of(s) + " surface to a B-spline surface");
        const long long points =
            static_cast<long long>(c.surface->NbUPoles()) * c.surface->NbVPoles();
        if (points > ctx_.options.limits.max_control_points)
            throw InputError(ctx_.file, name,
                             std::to_string(points) + " control points exceed the limit of " +
                                 std::to_string(ctx_.options.limits.max_control_points));
        BSplineSurface model = to_model(c.surface, name);
        validate_surface(model, ctx_.file, name);
        m_.surfaces.push_back(std::move(model));
        m_.origins.push_back({name, kind_of(s), c.exact, c.error});
        const GeomAdaptor_Surface adaptor(c.surface);
        const double tol = kApproximationFraction * std::max(face_tol, Precision::Confusion());
        uv_tolerance_ = std::min(adaptor.UResolution(tol), adaptor.VResolution(tol));
    }

    // The wire's coedges in order along it.
    BRepLoop loop(const TopoDS_Wire& wire, const TopoDS_Face& face) {
        BRepLoop loop;
        std::set<std::pair<int, bool>> seen; // (edge, reversed): a seam is used both ways
        for (BRepTools_WireExplorer e(wire, face); e.More(); e.Next()) {
            const TopoDS_Edge& edge = e.Current();
            if (edge.Orientation() != TopAbs_FORWARD && edge.Orientation() != TopAbs_REVERSED)
                continue;
            loop.coedges.push_back(coedge(edge, face));
            seen.insert({loop.coedges.back().edge, loop.coedges.back().reversed});
        }
        // Edges the explorer could not chain (a gap in the wire) stay, in
        // the wire's order, with a warning.
        bool missed = false;
        for (TopoDS_Iterator it(wire); it.More(); it.Next()) {
            const TopoDS_Edge& edge = TopoDS::Edge(it.Value());
            if (edge.Orientation() != TopAbs_FORWARD && edge.Orientation() != TopAbs_REVERSED)
                continue;
            const std::pair<int, bool> use{ctx_.edges.FindIndex(edge) - 1,
                                           edge.Orientation() == TopAbs_REVERSED};
            if (!seen.insert(use).second) continue;
            loop.coedges.push_back(coedge(edge, face));
            missed = true;
        }
        if (missed) unordered_.push_back(*name_);
        return loop;
    }

    // A pcurve on a periodic surface may lie a whole number of periods away
    // from the face's range: moved into it by its midpoint.
    void into_range(BSplineCurve& pc, double t0, double t1) const {
        const Vec3 mid = evaluate(pc, 0.5 * (t0 + t1)).point;
        for (int axis : {0, 1}) {
            const double period = period_[axis], lo = axis == 0 ? range_.u1 : range_.v1;
            if (period <= 0) continue;
            const double eps = 1e-9 * period; // a seam's far side stays where it is
            if (mid[axis] >= lo - eps && mid[axis] <= lo + period + eps) continue;
            const double shift = -std::floor((mid[axis] - lo) / period) * period;
            for (Vec3& p : pc.points) p[axis] += shift;
        }
    }

    BRepCoedge coedge(const TopoDS_Edge& edge, const TopoDS_Face& face) {
        BRepCoedge c;
        c.edge = ctx_.edges.FindIndex(edge) - 1;
        SEAMLESS_CHECK(c.edge >= 0, "a face's edge is in the shape's edge map");
        c.reversed = edge.Orientation() == TopAbs_REVERSED;
        read_edge(edge, face, c.edge);
        const BRepEdge& e = m_.brep.edges[c.edge];
        double f, l;
        const Handle(Geom2d_Curve) pc = BRep_Tool::CurveOnSurface(edge, face, f, l);
        if (pc.IsNull()) throw edge_error(c.edge, "has no curve on the face's surface");
        ConvertedCurve cc = convert_pcurve(pc, f, l, uv_tolerance_);
        if (!cc.ok || !(f < l)) throw edge_error(c.edge, "has a pcurve that cannot be converted");
        if (f != e.t0 || l != e.t1) reparametrise(cc.curve, f, l, e.t0, e.t1);
        into_range(cc.curve, e.t0, e.t1);
        if (map_ && !map_->identity()) {
            double error = 0;
            cc.curve = map_->carry(cc.curve, e.t0, e.t1, uv_tolerance_, error);
            if (cc.curve.points.empty())
                throw edge_error(c.edge, "has a pcurve that cannot be carried to the surface's "
                                         "NURBS form");
        }
        check_curve_size(cc.curve, c.edge);
        c.pcurve = static_cast<int>(m_.brep.pcurves.size());
        m_.brep.pcurves.push_back(std::move(cc.curve));
        return c;
    }

    // The edge's curve, range, vertices and tolerance, on its first use.
    void read_edge(const TopoDS_Edge& edge, const TopoDS_Face& face, int k) {
        if (edge_read_[k]) return;
        edge_read_[k] = true;
        BRepEdge& e = m_.brep.edges[k];
        const TopoDS_Edge fwd = TopoDS::Edge(edge.Oriented(TopAbs_FORWARD));
        TopoDS_Vertex first, last;
        TopExp::Vertices(fwd, first, last);
        if (first.IsNull() || last.IsNull()) throw edge_error(k, "has no vertex at an end");
        e.start = ctx_.vertices.FindIndex(first) - 1;
        e.end = ctx_.vertices.FindIndex(last) - 1;
        e.tolerance = BRep_Tool::Tolerance(fwd);
        if (BRep_Tool::Degenerated(fwd)) {
            BRep_Tool::Range(fwd, face, e.t0, e.t1);
            e.end = e.start;
            if (!(e.t0 < e.t1)) throw edge_error(k, "has an empty parameter range");
            return;
        }
        BRep_Tool::Range(fwd, e.t0, e.t1);
        if (!(e.t0 < e.t1)) throw edge_error(k, "has an empty parameter range");
        Handle(Geom_Curve) c = BRep_Tool::Curve(fwd, e.t0, e.t1); // located
        if (c.IsNull() && BRepLib::BuildCurve3d(fwd)) c = BRep_Tool::Curve(fwd, e.t0, e.t1);
        if (c.IsNull()) throw edge_error(k, "has no 3D curve");
        const double tol = kApproximationFraction * std::max(e.tolerance, Precision::Confusion());
        ConvertedCurve cc = convert_curve(c, e.t0, e.t1, tol);
        if (!cc.ok) throw edge_error(k, "has a 3D curve that cannot be converted");
        if (cc.error > 0) e.tolerance = std::max(e.tolerance, e.tolerance + cc.error);
        check_curve_size(cc.curve, k);
        e.curve = static_cast<int>(m_.brep.curves.size());
        m_.brep.curves.push_back(std::move(cc.curve));
    }

    void check_curve_size(const BSplineCurve& c, int edge) {
        if (c.size() > ctx_.options.limits.max_curve_points)
            throw edge_error(edge, "has " + std::to_string(c.size()) +
                                       " control points, over the limit of " +
                                       std::to_string(ctx_.options.limits.max_curve_points));
    }

    InputError edge_error(int edge, const std::string& what) const {
        return InputError(ctx_.file, *name_, "edge " + std::to_string(edge) + " " + what);
    }

    const FaceContext& ctx_;
    Model& m_;
    std::vector<bool> edge_read_;
    const std::string* name_ = nullptr; // the face being read, for messages
    double uv_tolerance_ = 0;           // of the face being read's pcurve approximations
    std::optional<ParameterMap> map_;   // of the face being read; none: the file's parameters
    FaceRange range_{};                 // of the face being read, in the file's parameters
    double period_[2] = {0, 0};         // its surface's periods in u and v (0: none)
    std::vector<std::string> unordered_;
};

} // namespace

void read_faces(const FaceContext& ctx, Model& m) {
    if (ctx.faces.Extent() > ctx.options.limits.max_surfaces)
        throw InputError(ctx.file, "",
                         "more than " + std::to_string(ctx.options.limits.max_surfaces) +
                             " surfaces exceed the limit");
    FaceReader reader(ctx, m);
    for (int k = 1; k <= ctx.faces.Extent(); ++k) {
        try {
            reader.read(k);
        } catch (const Standard_Failure& e) { // named by its face
            const char* what = e.GetMessageString();
            throw InputError(ctx.file, ctx.names[k - 1],
                             std::string("OpenCASCADE failed on it (") + e.DynamicType()->Name() +
                                 (what && *what ? std::string(": ") + what : std::string()) + ")");
        }
    }
    reader.finish();
}

} // namespace seamless::step_iges
