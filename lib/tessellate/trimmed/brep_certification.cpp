// SPDX-License-Identifier: MIT
#include <seamless/base/parallel/parallel.h>
#include <seamless/tessellate/trimmed/brep_certification.h>
#include <seamless/tessellate/trimmed/chord_bound.h>
#include <seamless/tessellate/trimmed/face_surface.h>
#include <seamless/tessellate/trimmed/triangle_bound.h>

#include <algorithm>
#include <limits>

namespace seamless {
namespace {

// A bound that is not a number is no bound: it counts as infinite.
double worst(double a, double b) {
    return std::max(a, b >= 0 ? b : std::numeric_limits<double>::infinity());
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
                const FaceSurface face(model.surfaces[mesh.triangle_surface[first[i]]]);
                const TriangleBound bound(face.surface(), face.closed_u(), face.closed_v());
                double b = 0;
                for (int t = first[i]; t < first[i + 1]; ++t) {
                    const auto& tri = mesh.triangles[t];
                    const auto& uv = mesh.corner_uvs[t];
                    b = worst(b, bound({UV{uv[0][0], uv[0][1]}, UV{uv[1][0], uv[1][1]},
                                        UV{uv[2][0], uv[2][1]}},
                                       {mesh.positions[tri[0]], mesh.positions[tri[1]],
                                        mesh.positions[tri[2]]}));
                }
                run_bound[i] = b;
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
