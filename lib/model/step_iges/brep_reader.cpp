// SPDX-License-Identifier: MIT
// The B-rep of a transferred file: the topology indexed (TopExp maps), read
// face by face with each surface in its exact NURBS form and the pcurves
// carried over to its parameters (brep_faces.cpp, parameter_map.h), then
// every coedge's pcurve checked against its edge's curve (brep_gaps.cpp).
// Not BRepBuilderAPI_NurbsConvert: it re-projects every pcurve on a
// converted surface onto it (seconds on the larger corpus files) and
// absorbs projections that went wrong into raised edge tolerances (0.18 mm
// on as1_motor); docs/results/cad.md has the figures.
#include <seamless/model/step_iges/brep_reader.h>

#include <seamless/base/error.h>
#include <seamless/model/step_iges/brep_faces.h>
#include <seamless/model/step_iges/brep_gaps.h>
#include <seamless/model/step_iges/messages.h>
#include <seamless/model/step_iges/pcurve_repair.h>
#include <seamless/model/step_iges/sewing.h>

#include <BRepClass3d.hxx>
#include <BRepLib.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>

#include <map>

namespace seamless::step_iges {
namespace {

void check_count(const std::string& file, int n, const char* what, const ModelLimits& limits) {
    if (n > limits.max_brep_items)
        throw InputError(file, "",
                         std::to_string(n) + " " + what + " exceed the limit of " +
                             std::to_string(limits.max_brep_items) + " B-rep items");
}

// Every face's shell and solid, in the transferred shape's order.
class ShellReader {
  public:
    ShellReader(const TransferredFile& t, const SewnShape& s, BRep& brep)
        : t_(t), shape_(s.shape), faces_(s.faces), brep_(brep) {}

    void read() {
        TopTools_IndexedMapOfShape solids;
        TopExp::MapShapes(shape_, TopAbs_SOLID, solids);
        std::map<std::string, int> uses;
        for (int k = 1; k <= solids.Extent(); ++k) {
            BRepSolid solid;
            solid.name = entity_label(t_.transfer, t_.model, solids(k), t_.iges);
            if (solid.name.empty()) solid.name = "solid-" + std::to_string(k - 1);
            if (int n = uses[solid.name]++; n > 0)
                solid.name.append(".").append(std::to_string(n + 1));
            const TopoDS_Solid s = TopoDS::Solid(solids(k));
            const TopoDS_Shell outer = BRepClass3d::OuterShell(s);
            if (!outer.IsNull()) solid.shells.push_back(shell(outer));
            for (TopoDS_Iterator it(s); it.More(); it.Next())
                if (it.Value().ShapeType() == TopAbs_SHELL && !it.Value().IsSame(outer))
                    solid.shells.push_back(shell(it.Value()));
            brep_.solids.push_back(std::move(solid));
        }
        // Shells outside solids.
        for (TopExp_Explorer e(shape_, TopAbs_SHELL, TopAbs_SOLID); e.More(); e.Next())
            shell(e.Current());
    }

  private:
    // The index of shell s, added with its faces on first use.
    int shell(const TopoDS_Shape& s) {
        if (int k = shells_.FindIndex(s)) return k - 1;
        shells_.Add(s);
        BRepShell shell;
        std::map<int, int> uses; // edge -> coedges of the shell's faces
        for (TopExp_Explorer e(s, TopAbs_FACE); e.More(); e.Next()) {
            const int f = faces_.FindIndex(e.Current()) - 1;
            if (f < 0) continue; // not a face of the model (cannot happen: the maps agree)
            shell.faces.push_back(f);
            for (const BRepLoop& loop : brep_.faces[f].loops)
                for (const BRepCoedge& c : loop.coedges)
                    if (!brep_.edges[c.edge].degenerate()) ++uses[c.edge];
        }
        shell.closed = !uses.empty();
        for (const auto& [edge, n] : uses) shell.closed = shell.closed && n == 2;
        brep_.shells.push_back(std::move(shell));
        return static_cast<int>(brep_.shells.size()) - 1;
    }

    const TransferredFile& t_; // for the solids' names
    const TopoDS_Shape& shape_;
    const TopTools_IndexedMapOfShape& faces_;
    BRep& brep_;
    TopTools_IndexedMapOfShape shells_;
};

} // namespace

Model read_brep(const TransferredFile& t, const std::vector<std::string>& names,
                const std::string& file, const ModelLoadOptions& options) {
    // Edges whose pcurves do not follow their 3D curve's parameter are
    // reparametrised (OpenCASCADE's own fix; flagged edges are left alone).
    BRepLib::SameParameter(t.shape, 1e-7);
    const SewnShape s = sew_free_faces(t, names, file);
    const std::string repaired = repair_pcurves(s.faces, s.names, file);
    FaceContext ctx{s.faces, s.names, file, options, {}, {}};
    // Edges and vertices of the faces only: a file's wireframe (AP242
    // annotations, construction curves) would be edges no face uses.
    for (int k = 1; k <= s.faces.Extent(); ++k) {
        TopExp::MapShapes(s.faces(k), TopAbs_EDGE, ctx.edges);
        TopExp::MapShapes(s.faces(k), TopAbs_VERTEX, ctx.vertices);
    }
    check_count(file, s.faces.Extent(), "faces", options.limits);
    check_count(file, ctx.edges.Extent(), "edges", options.limits);
    check_count(file, ctx.vertices.Extent(), "vertices", options.limits);

    Model m;
    m.source = file;
    if (!s.warning.empty()) m.warnings.push_back(s.warning);
    if (!repaired.empty()) m.warnings.push_back(repaired);
    read_faces(ctx, m);
    ShellReader(t, s, m.brep).read();
    check_gaps(m, file);
    validate_brep(m, file, options.limits);
    return m;
}

} // namespace seamless::step_iges
