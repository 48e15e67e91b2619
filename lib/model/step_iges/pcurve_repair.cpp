// SPDX-License-Identifier: MIT
#include <seamless/model/step_iges/pcurve_repair.h>

#include <seamless/model/step_iges/messages.h>

#include <BRepBndLib.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Geom2d_Curve.hxx>
#include <Geom_Curve.hxx>
#include <Geom_Surface.hxx>
#include <Precision.hxx>
#include <ShapeFix_Edge.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Vec2d.hxx>

#include <algorithm>
#include <cmath>
#include <set>

namespace seamless::step_iges {
namespace {

// A pcurve strays when it is this many edge tolerances from its 3D curve,
// or this fraction of the faces' diagonal (a tenth of the default
// deviation: a file may set an edge's tolerance to cover a pcurve on the
// wrong side of a face, which collapses the face in (u,v)). Below both,
// check_gaps raises the tolerance to the distance instead: a file's sloppy
// but consistent pcurves, which projection would not improve by much.
constexpr double kStray = 10;
constexpr double kVisible = 1e-4;
// The projection replaces a pcurve only when it is this much closer.
constexpr double kBetter = 4;
constexpr int kControl = 32; // intervals along the edge

// The largest distance between the pcurve on `face` and the 3D curve at
// the same parameters, sampled. Not ShapeAnalysis_Edge::CheckSameParameter:
// it reports at least the edge's tolerance.
double deviation(const TopoDS_Edge& edge, const TopoDS_Face& face) {
    double f3, l3, f2, l2;
    const Handle(Geom_Curve) c = BRep_Tool::Curve(edge, f3, l3);
    const Handle(Geom2d_Curve) pc = BRep_Tool::CurveOnSurface(edge, face, f2, l2);
    const Handle(Geom_Surface) s = BRep_Tool::Surface(face);
    if (c.IsNull() || pc.IsNull() || s.IsNull()) return 0;
    double dev = 0;
    for (int k = 0; k <= kControl; ++k) {
        const double t = f3 + (l3 - f3) * k / kControl;
        const gp_Pnt2d uv = pc->Value(f2 + (l2 - f2) * k / kControl);
        dev = std::max(dev, c->Value(t).Distance(s->Value(uv.X(), uv.Y())));
    }
    return dev;
}

// The pcurve(s) of edge on face, to put back when projection is worse.
struct SavedPcurves {
    Handle(Geom2d_Curve) c1, c2; // c2: the seam's other side
    double first = 0, last = 0;
    bool seam = false;
};

SavedPcurves save(const TopoDS_Edge& edge, const TopoDS_Face& face) {
    SavedPcurves s;
    s.seam = BRep_Tool::IsClosed(edge, face);
    const TopoDS_Edge fwd = TopoDS::Edge(edge.Oriented(TopAbs_FORWARD));
    s.c1 = BRep_Tool::CurveOnSurface(fwd, face, s.first, s.last);
    if (s.seam) {
        double f, l;
        s.c2 = BRep_Tool::CurveOnSurface(TopoDS::Edge(edge.Oriented(TopAbs_REVERSED)), face, f, l);
    }
    return s;
}

void restore(const TopoDS_Edge& edge, const TopoDS_Face& face, const SavedPcurves& s) {
    BRep_Builder b;
    const TopoDS_Edge fwd = TopoDS::Edge(edge.Oriented(TopAbs_FORWARD));
    const double tol = BRep_Tool::Tolerance(fwd);
    if (s.seam)
        b.UpdateEdge(fwd, s.c1, s.c2, face, tol);
    else
        b.UpdateEdge(fwd, s.c1, face, tol);
    if (!s.c1.IsNull()) b.Range(fwd, face, s.first, s.last);
}

// The face's wires as OpenCASCADE chains them, which the reader keeps
// (brep_faces.cpp): at a vertex with several edges the chaining looks at
// the pcurves' ends.
using Wires = std::vector<std::vector<TopoDS_Edge>>;

Wires chained_wires(const TopoDS_Face& face) {
    Wires wires;
    for (TopExp_Explorer w(face, TopAbs_WIRE); w.More(); w.Next()) {
        wires.emplace_back();
        for (BRepTools_WireExplorer e(TopoDS::Wire(w.Current()), face); e.More(); e.Next())
            wires.back().push_back(e.Current());
    }
    return wires;
}

bool same_chaining(const Wires& a, const Wires& b) {
    if (a.size() != b.size()) return false;
    for (size_t w = 0; w < a.size(); ++w) {
        if (a[w].size() != b[w].size()) return false;
        for (size_t i = 0; i < a[w].size(); ++i)
            if (!a[w][i].IsEqual(b[w][i])) return false; // same edge, same orientation
    }
    return true;
}

// Where the coedge (an oriented edge: a seam's side) starts or ends in (u,v).
gp_Pnt2d coedge_end(const TopoDS_Edge& coedge, const TopoDS_Face& face, bool at_end) {
    double f, l;
    const Handle(Geom2d_Curve) pc = BRep_Tool::CurveOnSurface(coedge, face, f, l);
    if (pc.IsNull()) return gp_Pnt2d(INFINITY, INFINITY);
    return pc->Value(at_end != (coedge.Orientation() == TopAbs_REVERSED) ? l : f);
}

// The loop's jumps in (u,v) at edge's coedges: from the previous coedge's
// end to its start, and from its end to the next one's start; `largest`
// of them, and whether each closes in space as the reader's validation
// asks (validate_brep): the surface along the jump stays within the
// tolerances of the vertex, as it does along a side of a face that a
// file's tolerance makes degenerate, and not across a period.
struct LoopJumps {
    double largest = 0;
    bool close = true;
};

LoopJumps loop_jumps(const TopoDS_Edge& edge, const TopoDS_Face& face, const Wires& wires) {
    constexpr int kSamples = 4;
    LoopJumps r;
    const Handle(Geom_Surface) s = BRep_Tool::Surface(face);
    const auto jump = [&](const TopoDS_Edge& from, const TopoDS_Edge& to) {
        const gp_Pnt2d a = coedge_end(from, face, true), b = coedge_end(to, face, false);
        r.largest = std::max(r.largest, a.Distance(b));
        const TopoDS_Vertex v = TopExp::FirstVertex(to, true);
        if (v.IsNull() || s.IsNull()) return;
        const gp_Pnt p = BRep_Tool::Pnt(v);
        const double tol = BRep_Tool::Tolerance(v) +
                           std::max(BRep_Tool::Tolerance(from), BRep_Tool::Tolerance(to));
        for (int i = 0; i <= kSamples; ++i) {
            const gp_XY uv = a.XY() + (b.XY() - a.XY()) * (double(i) / kSamples);
            if (!(s->Value(uv.X(), uv.Y()).Distance(p) <= tol)) r.close = false;
        }
    };
    for (const auto& w : wires)
        for (size_t i = 0; i < w.size(); ++i) {
            if (!w[i].IsSame(edge)) continue;
            jump(w[(i + w.size() - 1) % w.size()], w[i]);
            jump(w[i], w[(i + 1) % w.size()]);
        }
    return r;
}

// The periods of the face's surface in u and v (0: none). A closed surface
// that is not periodic (a B-spline closed in u) has its seam twice in
// (u,v): its range is the period.
gp_Vec2d periods(const TopoDS_Face& face) {
    const Handle(Geom_Surface) s = BRep_Tool::Surface(face);
    if (s.IsNull()) return {0, 0};
    double u0, u1, v0, v1;
    s->Bounds(u0, u1, v0, v1);
    double pu = s->IsUPeriodic() ? s->UPeriod() : s->IsUClosed() ? u1 - u0 : 0;
    double pv = s->IsVPeriodic() ? s->VPeriod() : s->IsVClosed() ? v1 - v0 : 0;
    if (!std::isfinite(pu)) pu = 0;
    if (!std::isfinite(pv)) pv = 0;
    return {pu, pv};
}

// On a periodic or closed surface the projections may land a period away
// from where the loop runs, or the file's loop may run a period away from
// where its 3D curves are: each coedge of the wire after `anchor` (a
// pcurve the repair left alone) is moved by whole periods to start where
// the one before it ends. Seams stay: their two sides are where they are.
void unwrap_wire(const std::vector<TopoDS_Edge>& w, size_t anchor, const TopoDS_Face& face,
                 gp_Vec2d p) {
    for (size_t i = 1; i < w.size(); ++i) {
        const TopoDS_Edge& c = w[(anchor + i) % w.size()];
        if (BRep_Tool::IsClosed(c, face)) continue;
        const gp_Pnt2d target = coedge_end(w[(anchor + i - 1) % w.size()], face, true);
        const gp_Pnt2d start = coedge_end(c, face, false);
        const gp_Vec2d by(p.X() > 0 ? std::round((target.X() - start.X()) / p.X()) * p.X() : 0,
                          p.Y() > 0 ? std::round((target.Y() - start.Y()) / p.Y()) * p.Y() : 0);
        if (!(by.Magnitude() > 0) || !std::isfinite(by.Magnitude())) continue;
        SavedPcurves m = save(c, face);
        m.c1 = Handle(Geom2d_Curve)::DownCast(m.c1->Translated(by));
        restore(c, face, m);
    }
}

// Replaces edge's pcurve on face by the projection of its 3D curve when
// that is kBetter times closer; returns the deviation after.
double reproject(const TopoDS_Edge& edge, const TopoDS_Face& face, double before) {
    const SavedPcurves saved = save(edge, face);
    // Not a seam: its projection may swap the two sides.
    if (saved.c1.IsNull() || saved.seam) return before;
    ShapeFix_Edge fix;
    double after = before;
    try {
        // Not FixRemovePCurve: it keeps a pcurve whose ends meet the
        // vertices, however far its middle strays.
        restore(edge, face, SavedPcurves{});
        if (fix.FixAddPCurve(edge, face, false, Precision::Confusion()))
            after = deviation(edge, face);
    } catch (const Standard_Failure&) { // projection failed: keep the file's
        after = before;
    }
    if (after * kBetter <= before) return after;
    restore(edge, face, saved);
    return before;
}

// Whether every junction of the face's loops closes (loop_jumps).
bool loops_close(const TopoDS_Face& face, const Wires& wires) {
    for (const auto& w : wires)
        for (const TopoDS_Edge& c : w)
            if (!loop_jumps(c, face, wires).close) return false;
    return true;
}

// Recomputes the face's straying pcurves, all or nothing: undone where the
// face's loops then chain differently, or do not close.
// Appends "name (before -> after)" per pcurve recomputed to `fixed`.
void repair_face(const TopoDS_Face& face, double visible, const std::string& name,
                 std::vector<std::string>& fixed) {
    std::vector<std::pair<TopoDS_Edge, SavedPcurves>> undo; // every pcurve changed
    std::vector<std::string> recomputed;
    Wires wires;
    std::set<const void*> seen; // a seam edge appears twice
    for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next()) {
        const TopoDS_Edge edge = TopoDS::Edge(e.Current());
        if (BRep_Tool::Degenerated(edge) || !seen.insert(edge.TShape().get()).second) continue;
        if (!BRep_Tool::IsGeometric(edge)) continue; // no 3D curve to project
        const double tol = std::max(BRep_Tool::Tolerance(edge), Precision::Confusion());
        double before = 0;
        try {
            before = deviation(edge, face);
        } catch (const Standard_Failure&) {
            continue; // left to the reader, which names the edge
        }
        if (before <= std::min(kStray * tol, visible) || before <= Precision::Confusion()) continue;
        if (undo.empty()) wires = chained_wires(face);
        const SavedPcurves saved = save(edge, face);
        const double after = reproject(edge, face, before);
        if (after < before) {
            undo.push_back({edge, saved});
            recomputed.push_back(name + " (" + fmt(before) + " -> " + fmt(after) + ")");
        }
    }
    if (undo.empty()) return;
    // Every pcurve but a seam's unwrapped along its wire, from one the
    // repair left alone.
    std::set<const void*> touched;
    for (const auto& u : undo) touched.insert(u.first.TShape().get());
    const std::set<const void*> repaired = touched;
    if (const gp_Vec2d p = periods(face); p.Magnitude() > 0)
        for (const auto& w : wires) {
            if (w.empty()) continue;
            size_t anchor = 0;
            while (anchor < w.size() && repaired.count(w[anchor].TShape().get())) ++anchor;
            for (const TopoDS_Edge& c : w)
                if (!BRep_Tool::IsClosed(c, face) && touched.insert(c.TShape().get()).second)
                    undo.push_back({c, save(c, face)});
            unwrap_wire(w, anchor % w.size(), face, p);
        }
    if (!same_chaining(chained_wires(face), wires) || !loops_close(face, wires)) {
        for (auto u = undo.rbegin(); u != undo.rend(); ++u) restore(u->first, face, u->second);
        return;
    }
    fixed.insert(fixed.end(), recomputed.begin(), recomputed.end());
}

} // namespace

std::string repair_pcurves(const TopTools_IndexedMapOfShape& faces,
                           const std::vector<std::string>& names, const std::string& file) {
    Bnd_Box box;
    for (int k = 1; k <= faces.Extent(); ++k) BRepBndLib::Add(faces(k), box);
    const double visible = box.IsVoid() ? 0 : kVisible * std::sqrt(box.SquareExtent());
    std::vector<std::string> fixed;
    for (int k = 1; k <= faces.Extent(); ++k)
        repair_face(TopoDS::Face(faces(k).Oriented(TopAbs_FORWARD)), visible, names[k - 1], fixed);
    if (fixed.empty()) return {};
    return file + ": recomputed " + count_of(fixed.size(), "pcurve") +
           " by projecting the edge's 3D curve, where the file's strayed from it "
           "(distances before and after): " +
           list_names(fixed);
}

} // namespace seamless::step_iges
