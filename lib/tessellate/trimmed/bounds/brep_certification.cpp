// SPDX-License-Identifier: MIT
#include <seamless/base/parallel/parallel.h>
#include <seamless/tessellate/trimmed/bounds/brep_certification.h>
#include <seamless/tessellate/trimmed/bounds/chord_bound.h>
#include <seamless/tessellate/trimmed/bounds/pole_fan.h>
#include <seamless/tessellate/trimmed/bounds/triangle_bound.h>
#include <seamless/tessellate/trimmed/face_surface.h>

#include <algorithm>
#include <limits>

namespace seamless {
namespace {

// A bound that is not a number is no bound: it counts as infinite.
double worst(double a, double b) {
    return std::max(a, b >= 0 ? b : std::numeric_limits<double>::infinity());
}

// The (u,v) points of the degenerate edges of the faces on `surface`.
std::vector<UV> side_points(const Model& model, const std::vector<EdgePolyline>& lines,
                            int surface) {
    std::vector<UV> out;
    for (const BRepFace& f : model.brep.faces) {
        if (f.surface != surface) continue;
        for (const BRepLoop& loop : f.loops)
            for (const BRepCoedge& c : loop.coedges) {
                if (!model.brep.edges[c.edge].degenerate() || c.pcurve < 0) continue;
                for (double t : lines[c.edge].t) {
                    const Vec3 p = evaluate(model.brep.pcurves[c.pcurve], t).point;
                    out.push_back({p.x, p.y});
                }
            }
    }
    return out;
}

// The largest bound over the triangles [begin, end) of one surface: pole
// fans geometrically (pole_fan.h), the others by TriangleBound.
double run_of_surface(const Model& model, const std::vector<EdgePolyline>& lines,
                      const TriangleMesh& mesh, int begin, int end) {
    const int surface = mesh.triangle_surface[begin];
    const FaceSurface face(model.surfaces[surface]);
    const TriangleBound bound(face.surface(), face.closed_u(), face.closed_v());
    std::vector<RunTriangle> run(end - begin);
    for (int t = begin; t < end; ++t) {
        RunTriangle& r = run[t - begin];
        for (int k = 0; k < 3; ++k) {
            r.uv[k] = {mesh.corner_uvs[t][k][0], mesh.corner_uvs[t][k][1]};
            r.id[k] = mesh.triangles[t][k];
            r.Q[k] = mesh.positions[r.id[k]];
        }
    }
    std::vector<char> handled;
    double b =
        pole_fan_bounds(bound, face.surface(), run, side_points(model, lines, surface), handled);
    for (size_t k = 0; k < run.size(); ++k)
        if (!handled[k]) b = worst(b, bound(run[k].uv, run[k].Q));
    return b;
}

} // namespace

BRepBound certify_brep(const Model& model, const std::vector<EdgePolyline>& lines,
                       const TriangleMesh& mesh, int threads) {
    // Runs of one surface (a face's triangles are written together): one
    // TriangleBound, whose Bezier extraction is the costly part, per run.
    std::vector<int> first{0};
    for (int t = 1; t < mesh.triangle_count(); ++t)
        if (mesh.triangle_surface[t] != mesh.triangle_surface[t - 1]) first.push_back(t);
    first.push_back(mesh.triangle_count());
    const int runs = static_cast<int>(first.size()) - 1;
    const int edges = static_cast<int>(lines.size());
    // Per item slots, reduced in order: the same maximum on any thread count.
    std::vector<double> run_bound(std::max(runs, 0), 0.0), edge_bound(edges, 0.0);
    parallel_chunks(runs + edges, threads, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) {
            if (i < runs) {
                if (first[i] == first[i + 1]) continue;
                run_bound[i] = run_of_surface(model, lines, mesh, first[i], first[i + 1]);
            } else {
                const int e = i - runs;
                const BRepEdge& edge = model.brep.edges[e];
                const EdgePolyline& line = lines[e];
                if (edge.degenerate() || line.t.size() < 2) continue;
                const ChordBound bound(model.brep.curves[edge.curve]);
                double b = 0;
                for (size_t k = 0; k + 1 < line.t.size(); ++k)
                    b = worst(b,
                              bound(line.t[k], line.t[k + 1], line.points[k], line.points[k + 1]));
                edge_bound[e] = b;
            }
        }
    });
    BRepBound r;
    for (double b : run_bound) r.triangles = std::max(r.triangles, b);
    for (double b : edge_bound) r.chords = std::max(r.chords, b);
    return r;
}

} // namespace seamless
