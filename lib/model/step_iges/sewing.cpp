// SPDX-License-Identifier: MIT
#include <seamless/model/step_iges/sewing.h>

#include <seamless/model/step_iges/messages.h>

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepLib.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Solid.hxx>

#include <algorithm>
#include <cmath>

namespace seamless::step_iges {
namespace {

// Below this fraction of the diagonal a gap is rounding.
constexpr double kMinTolerance = 1e-6;

SewnShape as_is(const TransferredFile& t, const std::vector<std::string>& names) {
    SewnShape s;
    s.shape = t.shape;
    s.faces = t.faces;
    s.names = names;
    return s;
}

double sewing_tolerance(const TransferredFile& t) {
    Bnd_Box box;
    BRepBndLib::Add(t.shape, box);
    double tol = box.IsVoid() ? 0 : kMinTolerance * std::sqrt(box.SquareExtent());
    for (TopExp_Explorer e(t.shape, TopAbs_EDGE); e.More(); e.Next())
        tol = std::max(tol, BRep_Tool::Tolerance(TopoDS::Edge(e.Current())));
    return tol;
}

// Each closed shell of the sewn shape as a solid, oriented outward; open
// shells and faces as they are.
TopoDS_Shape solids_of(const TopoDS_Shape& sewn, int& closed) {
    BRep_Builder b;
    TopoDS_Compound out;
    b.MakeCompound(out);
    closed = 0;
    for (TopExp_Explorer e(sewn, TopAbs_SHELL); e.More(); e.Next()) {
        const TopoDS_Shell shell = TopoDS::Shell(e.Current());
        if (BRep_Tool::IsClosed(shell)) {
            TopoDS_Solid solid = BRepBuilderAPI_MakeSolid(shell).Solid();
            BRepLib::OrientClosedSolid(solid);
            b.Add(out, solid);
            ++closed;
        } else {
            b.Add(out, shell);
        }
    }
    for (TopExp_Explorer e(sewn, TopAbs_FACE, TopAbs_SHELL); e.More(); e.Next())
        b.Add(out, e.Current());
    return out;
}

} // namespace

SewnShape sew_free_faces(const TransferredFile& t, const std::vector<std::string>& names,
                         const std::string& file) {
    if (t.faces.Extent() < 2) return as_is(t, names);
    for (TopExp_Explorer e(t.shape, TopAbs_SHELL); e.More(); e.Next()) return as_is(t, names);
    const double tol = sewing_tolerance(t);
    BRepBuilderAPI_Sewing sewing(tol);
    for (int k = 1; k <= t.faces.Extent(); ++k) sewing.Add(t.faces(k));
    sewing.Perform();
    if (sewing.SewedShape().IsNull()) return as_is(t, names);
    SewnShape s;
    int closed = 0;
    s.shape = solids_of(sewing.SewedShape(), closed);
    // Names through the sewing's history: a sewn face is its file face's.
    TopTools_IndexedMapOfShape sewn_faces;
    TopExp::MapShapes(s.shape, TopAbs_FACE, sewn_faces);
    std::vector<std::string> sewn_names(sewn_faces.Extent());
    for (int k = 1; k <= t.faces.Extent(); ++k) {
        const TopoDS_Shape& now =
            sewing.IsModified(t.faces(k)) ? sewing.Modified(t.faces(k)) : t.faces(k);
        if (const int i = sewn_faces.FindIndex(now)) sewn_names[i - 1] = names[k - 1];
    }
    for (int i = 1; i <= sewn_faces.Extent(); ++i) {
        s.faces.Add(sewn_faces(i));
        if (sewn_names[i - 1].empty()) sewn_names[i - 1] = "face-" + std::to_string(i - 1);
    }
    s.names = std::move(sewn_names);
    s.warning = file + ": sewed " + count_of(static_cast<size_t>(t.faces.Extent()), "free face") +
                " within " + fmt(tol) + " (" + std::to_string(sewing.NbContigousEdges()) +
                " edges joined, " + std::to_string(sewing.NbFreeEdges()) + " left free, " +
                count_of(static_cast<size_t>(closed), "closed shell") + ")";
    return s;
}

} // namespace seamless::step_iges
