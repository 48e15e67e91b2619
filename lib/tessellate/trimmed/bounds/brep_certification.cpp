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
// fans geometrically (pole_fan.h), the others by TriangleBound, which
// needs the full bound only of a triangle that may exceed `floor` (a bound
// already found elsewhere) and the run's largest so far.
double run_of_surface(const Model& model, const std::vector<EdgePolyline>& lines,
                      const TriangleMesh& mesh, int begin, int end, double floor) {
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
        if (!handled[k]) b = worst(b, bound(run[k].uv, run[k].Q, std::max(b, floor)));
    return b;
}

// The largest bound over the segments of one edge's polyline (0 for a
// degenerate edge), `floor` as in run_of_surface.
double edge_bound(const Model& model, const EdgePolyline& line, int e, double floor) {
    const BRepEdge& edge = model.brep.edges[e];
    if (edge.degenerate() || line.t.size() < 2) return 0;
    const ChordBound bound(model.brep.curves[edge.curve]);
    double b = 0;
    for (size_t k = 0; k + 1 < line.t.size(); ++k)
        b = worst(b, bound(line.t[k], line.t[k + 1], line.points[k], line.points[k + 1],
                           std::max(b, floor)));
    return b;
}

// The total degree of a work item's Bezier pieces (a run's surface, an
// edge's curve extruded: chord_bound.h), the measure of its cost per piece.
int total_degree(const Model& model, const TriangleMesh& mesh, int first_triangle, int edge) {
    if (edge < 0) {
        const BSplineSurface& s = model.surfaces[mesh.triangle_surface[first_triangle]];
        return s.degree_u + s.degree_v;
    }
    const BRepEdge& e = model.brep.edges[edge];
    return e.degenerate() ? 0 : model.brep.curves[e.curve].degree + 1;
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
    const int runs = mesh.triangle_count() > 0 ? static_cast<int>(first.size()) - 1 : 0;
    const int edges = static_cast<int>(lines.size());
    // Per item slots, reduced in order: the same maximum on any thread count.
    std::vector<double> bounds(runs + edges, 0.0);
    std::vector<int> degree(runs + edges);
    for (int i = 0; i < runs + edges; ++i)
        degree[i] = total_degree(model, mesh, i < runs ? first[i] : 0, i < runs ? -1 : i - runs);
    // In waves of rising degree: the cheap items' largest bounds are the
    // floor below which the costlier ones need no full bound. Each wave
    // sees only the earlier waves' results, so every figure is the same on
    // any thread count.
    BRepBound r;
    int below = -1;
    for (int limit : {4, 8, std::numeric_limits<int>::max()}) {
        std::vector<int> wave;
        for (int i = 0; i < runs + edges; ++i)
            if (degree[i] > below && degree[i] <= limit) wave.push_back(i);
        below = limit;
        const BRepBound floor = r;
        parallel_chunks(static_cast<int>(wave.size()), threads, [&](int begin, int end) {
            for (int k = begin; k < end; ++k) {
                const int i = wave[k];
                bounds[i] = i < runs ? run_of_surface(model, lines, mesh, first[i], first[i + 1],
                                                      floor.triangles)
                                     : edge_bound(model, lines[i - runs], i - runs, floor.chords);
            }
        });
        for (int i : wave) {
            double& figure = i < runs ? r.triangles : r.chords;
            figure = worst(figure, bounds[i]);
        }
    }
    return r;
}

} // namespace seamless
