// SPDX-License-Identifier: MIT
// flatten_assembly (assembly.h): every instance of a part copied into one
// B-rep in world coordinates. Affine maps act on NURBS control points
// exactly, so each copy is the part's geometry placed, not an approximation.
#include <seamless/model/assembly.h>

#include <seamless/base/error.h>
#include <seamless/model/model.h>

namespace seamless {
namespace {

double determinant(const AffineMap& map) {
    const double* a = map.m;
    return a[0] * (a[5] * a[10] - a[6] * a[9]) - a[1] * (a[4] * a[10] - a[6] * a[8]) +
           a[2] * (a[4] * a[9] - a[5] * a[8]);
}

// Copies items of `from` into `to` on first use, through index maps that
// are fresh for every instance.
class InstanceCopier {
  public:
    InstanceCopier(const Model& from, Model& to, const AffineMap& map, CopyNames& face_names)
        : from_(from), to_(to), map_(map), stretch_(map.stretch()), mirror_(determinant(map) < 0),
          face_names_(face_names), surface_(from.surfaces.size(), -1),
          edge_(from.brep.edges.size(), -1), vertex_(from.brep.vertices.size(), -1),
          curve_(from.brep.curves.size(), -1), pcurve_(from.brep.pcurves.size(), -1) {}

    int face(int f) {
        BRepFace face = from_.brep.faces[f];
        face.surface = surface(face.surface);
        face.name = face_names_(face.name);
        if (mirror_) face.reversed = !face.reversed;
        for (BRepLoop& loop : face.loops)
            for (BRepCoedge& ce : loop.coedges) {
                ce.edge = edge(ce.edge);
                ce.pcurve = copy_once(pcurve_, ce.pcurve, [&](int k) {
                    to_.brep.pcurves.push_back(from_.brep.pcurves[k]);
                    return to_.brep.pcurves.size();
                });
            }
        to_.brep.faces.push_back(std::move(face));
        return static_cast<int>(to_.brep.faces.size()) - 1;
    }

  private:
    // map[k], filled by add(k) (which returns the new size) on first use.
    template <class Add> static int copy_once(std::vector<int>& map, int k, Add add) {
        if (map[k] < 0) map[k] = static_cast<int>(add(k)) - 1;
        return map[k];
    }

    int surface(int s) {
        return copy_once(surface_, s, [&](int k) {
            BSplineSurface copy = from_.surfaces[k];
            for (Vec3& p : copy.points) p = map_(p);
            to_.surfaces.push_back(std::move(copy));
            if (from_.origins.size() == from_.surfaces.size())
                to_.origins.push_back(from_.origins[k]);
            return to_.surfaces.size();
        });
    }

    int edge(int e) {
        return copy_once(edge_, e, [&](int k) {
            BRepEdge copy = from_.brep.edges[k];
            if (!copy.degenerate())
                copy.curve = copy_once(curve_, copy.curve, [&](int c) {
                    BSplineCurve curve = from_.brep.curves[c];
                    for (Vec3& p : curve.points) p = map_(p);
                    to_.brep.curves.push_back(std::move(curve));
                    return to_.brep.curves.size();
                });
            copy.start = vertex(copy.start);
            copy.end = vertex(copy.end);
            copy.tolerance *= stretch_;
            to_.brep.edges.push_back(copy);
            return to_.brep.edges.size();
        });
    }

    int vertex(int v) {
        return copy_once(vertex_, v, [&](int k) {
            BRepVertex copy = from_.brep.vertices[k];
            copy.point = map_(copy.point);
            copy.tolerance *= stretch_;
            to_.brep.vertices.push_back(copy);
            return to_.brep.vertices.size();
        });
    }

    const Model& from_;
    Model& to_;
    const AffineMap& map_;
    double stretch_;
    bool mirror_;
    CopyNames& face_names_;
    std::vector<int> surface_, edge_, vertex_, curve_, pcurve_;
};

// Surfaces no face lies on (free surfaces), copied once as they are.
void copy_free_surfaces(const Model& m, Model& out) {
    std::vector<bool> used(m.surfaces.size(), false);
    for (const BRepFace& f : m.brep.faces) used[f.surface] = true;
    for (size_t s = 0; s < m.surfaces.size(); ++s) {
        if (used[s]) continue;
        out.surfaces.push_back(m.surfaces[s]);
        if (m.origins.size() == m.surfaces.size()) out.origins.push_back(m.origins[s]);
    }
}

} // namespace

Model flatten_assembly(const Model& m) {
    if (!m.assembly.has_tree()) return m;
    Model out;
    out.source = m.source;
    out.warnings = m.warnings;
    const std::vector<PartRange> ranges = part_ranges(m.assembly);
    const std::vector<AffineMap> world = world_placements(m.assembly);
    const std::vector<int> colours = face_colours(m);
    bool coloured = false;
    for (int c : colours) coloured = coloured || c >= 0;
    CopyNames face_names, solid_names;
    // Where each node's copy starts, for the layers.
    std::vector<int> first_face(m.assembly.nodes.size(), -1), first_solid = first_face;
    for (size_t n = 0; n < m.assembly.nodes.size(); ++n) {
        const int p = m.assembly.nodes[n].part;
        if (p < 0) continue;
        const PartRange& r = ranges[p];
        InstanceCopier copy(m, out, world[n], face_names);
        const int f0 = static_cast<int>(out.brep.faces.size());
        const int s0 = static_cast<int>(out.brep.shells.size());
        first_face[n] = f0;
        first_solid[n] = static_cast<int>(out.brep.solids.size());
        for (int f = r.first_face; f < r.first_face + r.face_count; ++f) {
            copy.face(f);
            if (coloured) out.assembly.face_colours.push_back(colours[f]);
        }
        for (int s = r.first_shell; s < r.first_shell + r.shell_count; ++s) {
            BRepShell shell = m.brep.shells[s];
            for (int& f : shell.faces) f += f0 - r.first_face;
            out.brep.shells.push_back(std::move(shell));
        }
        for (int s = r.first_solid; s < r.first_solid + r.solid_count; ++s) {
            BRepSolid solid = m.brep.solids[s];
            for (int& sh : solid.shells) sh += s0 - r.first_shell;
            solid.name = solid_names(solid.name);
            out.brep.solids.push_back(std::move(solid));
        }
    }
    copy_free_surfaces(m, out);
    if (out.surfaces.empty())
        throw InputError(m.source, "assembly.nodes", "no node places a part: nothing to show");
    if (coloured) out.assembly.colours = m.assembly.colours;
    out.assembly.layers = placed_layers(m, first_face, first_solid);
    return out;
}

} // namespace seamless
