// SPDX-License-Identifier: MIT
#include <seamless/mesh/deviation/brep_deviation.h>

#include <seamless/base/check.h>
#include <seamless/base/parallel/parallel.h>
#include <seamless/mesh/deviation/deviation_accumulator.h>
#include <seamless/mesh/deviation/mesh_distance.h>
#include <seamless/mesh/deviation/nearest_samples.h>
#include <seamless/mesh/deviation/spline_projection.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <utility>

namespace seamless {
namespace {

// Vertices or triangles per item of the mesh -> face pass: fixed, so that
// the sums are the same for any thread count.
constexpr int kBlock = 256;

struct BRepSampled {
    std::vector<std::unique_ptr<FaceRegion>> regions; // per face
    std::vector<FaceSample> faces;                    // in face order
    std::vector<EdgeSample> edges;                    // in edge order
};

template <class T> std::vector<T> concatenate(std::vector<std::vector<T>>& parts) {
    std::vector<T> all;
    size_t n = 0;
    for (const auto& p : parts) n += p.size();
    all.reserve(n);
    for (auto& p : parts) {
        all.insert(all.end(), p.begin(), p.end());
        std::vector<T>().swap(p);
    }
    return all;
}

// Face -> mesh: the faces' and edges' samples, each to the closest point of
// the mesh; the samples are kept for the way back.
DeviationStats faces_to_mesh(const Model& model, const TriangleMesh& mesh,
                             const BRepDeviationOptions& o, BRepSampled& s) {
    const BRep& brep = model.brep;
    const int nf = static_cast<int>(brep.faces.size()), ne = static_cast<int>(brep.edges.size());
    BRepSamplingOptions sampling = o.sampling;
    sampling.spacing = o.relative_spacing * brep_diagonal(model);
    FaceRegionOptions region_options;
    region_options.samples_per_coedge = o.pcurve_samples;
    region_options.spacing = sampling.spacing / 4;
    const MeshDistance to_mesh(mesh);
    std::vector<DeviationAccumulator> acc(nf + ne);
    std::vector<std::vector<FaceSample>> face_parts(nf);
    std::vector<std::vector<EdgeSample>> edge_parts(ne);
    s.regions.resize(nf);
    // Items [0, nf) are faces, [nf, nf + ne) edges; each writes its own slots.
    parallel_chunks(nf + ne, o.threads, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) {
            if (i < nf) {
                s.regions[i] = std::make_unique<FaceRegion>(model, i, region_options);
                face_parts[i] = face_samples(model, i, *s.regions[i], sampling);
                if (!to_mesh.empty())
                    for (const FaceSample& f : face_parts[i]) acc[i].add(to_mesh(f.point), f.point);
            } else {
                edge_parts[i - nf] = edge_samples(model, i - nf, sampling);
                if (!to_mesh.empty())
                    for (const EdgeSample& e : edge_parts[i - nf])
                        acc[i].add(to_mesh(e.point), e.point);
            }
        }
    });
    s.faces = concatenate(face_parts);
    s.edges = concatenate(edge_parts);
    return combine(acc);
}

// What one mesh -> face query needs.
struct FaceSearch {
    const Model& model;
    const BRepDeviationOptions& options;
    const BRepSampled& sampled;
    const NearestSamples& face_tree;
    const NearestSamples& edge_tree;
    // Per edge, the longest chord between consecutive samples: a point of the
    // curve is within it of a sample (the arc between two samples is shorter
    // than twice its chord), so a sample farther than best + it cannot lead
    // to a closer point.
    std::vector<double> edge_piece;
    // Per edge, the faces using it with the pcurve of each use.
    std::vector<std::vector<std::pair<int, int>>> edge_uses;
};

std::vector<std::vector<std::pair<int, int>>> edge_uses(const BRep& brep) {
    std::vector<std::vector<std::pair<int, int>>> uses(brep.edges.size());
    for (int f = 0; f < static_cast<int>(brep.faces.size()); ++f)
        for (const BRepLoop& loop : brep.faces[f].loops)
            for (const BRepCoedge& c : loop.coedges)
                if (c.pcurve >= 0) uses[c.edge].push_back({f, c.pcurve});
    return uses;
}

std::vector<double> edge_pieces(const BRep& brep, const std::vector<EdgeSample>& samples) {
    std::vector<double> piece(brep.edges.size(), 0.0);
    for (size_t i = 1; i < samples.size(); ++i)
        if (samples[i].edge == samples[i - 1].edge)
            piece[samples[i].edge] =
                std::max(piece[samples[i].edge], distance(samples[i].point, samples[i - 1].point));
    return piece;
}

// Distance from x to the closest point found on the faces (see the header).
double distance_to_faces(const FaceSearch& q, Vec3 x, std::vector<int>& nearest) {
    const BRep& brep = q.model.brep;
    double best = HUGE_VAL;
    int tried[8], n_tried = 0;
    const int max_tried = std::clamp(q.options.max_faces_tried, 0, 8);
    q.face_tree.nearest(x, q.options.face_neighbours, nearest);
    for (int k = 0; k < static_cast<int>(nearest.size()); ++k) {
        const FaceSample& s = q.sampled.faces[nearest[k]];
        best = std::min(best, distance(s.point, x));
        const bool new_face = std::find(tried, tried + n_tried, s.face) == tried + n_tried;
        if (new_face && n_tried < max_tried)
            tried[n_tried++] = s.face;
        else if (k >= q.options.newton_seeds)
            continue;
        const BSplineSurface& surface = q.model.surfaces[brep.faces[s.face].surface];
        const SurfaceProjection p =
            project_to_surface(surface, x, s.u, s.v, q.options.newton_iterations);
        if (q.sampled.regions[s.face]->contains(p.u, p.v)) best = std::min(best, p.distance);
    }
    q.edge_tree.nearest(x, q.options.edge_neighbours, nearest);
    int edges_tried[8], n_edges = 0;
    for (const int i : nearest) {
        const EdgeSample& s = q.sampled.edges[i];
        const double d = distance(s.point, x);
        // Onto each face of the edge from the sample's (u,v) there, once per
        // edge and however far the sample: a point beside an edge whose
        // nearest face samples all lie on other faces (a wall's, denser near
        // the edge than a large plane's) would otherwise count its distance
        // to the edge or to those faces, not to the face it lies on.
        if (std::find(edges_tried, edges_tried + n_edges, s.edge) == edges_tried + n_edges &&
            n_edges < 8) {
            edges_tried[n_edges++] = s.edge;
            for (const auto& [face, pcurve] : q.edge_uses[s.edge]) {
                const Vec3 uv = evaluate_point(brep.pcurves[pcurve], s.t);
                const SurfaceProjection p =
                    project_to_surface(q.model.surfaces[brep.faces[face].surface], x, uv.x, uv.y,
                                       q.options.newton_iterations);
                if (q.sampled.regions[face]->contains(p.u, p.v)) best = std::min(best, p.distance);
            }
        }
        if (d - q.edge_piece[s.edge] >= best) continue;
        const BRepEdge& e = brep.edges[s.edge];
        best = std::min(best, d);
        best = std::min(best, project_to_curve(brep.curves[e.curve], x, s.t, e.t0, e.t1,
                                               q.options.newton_iterations)
                                  .distance);
    }
    return best;
}

// Mesh -> face: every vertex a triangle uses once, then the triangles' other
// barycentric points; fixed blocks of each, combined in order.
DeviationStats mesh_to_faces(const Model& model, const TriangleMesh& mesh,
                             const BRepDeviationOptions& o, const BRepSampled& s) {
    if (s.faces.empty() && s.edges.empty()) return {};
    std::vector<Vec3> points(s.faces.size());
    for (size_t i = 0; i < s.faces.size(); ++i) points[i] = s.faces[i].point;
    const NearestSamples face_tree(points);
    points.resize(s.edges.size());
    for (size_t i = 0; i < s.edges.size(); ++i) points[i] = s.edges[i].point;
    const NearestSamples edge_tree(points);
    std::vector<Vec3>().swap(points);
    const FaceSearch q{
        model, o, s, face_tree, edge_tree, edge_pieces(model.brep, s.edges), edge_uses(model.brep)};

    std::vector<char> used(mesh.positions.size(), 0);
    for (const auto& t : mesh.triangles)
        for (const int v : t) used[v] = 1;
    std::vector<std::array<double, 3>> bary = barycentric_points(o.triangle_level);
    std::erase_if(
        bary, [](const std::array<double, 3>& w) { return w[0] == 1 || w[1] == 1 || w[2] == 1; });
    const int nv = mesh.vertex_count(), nt = mesh.triangle_count();
    const int vertex_blocks = (nv + kBlock - 1) / kBlock;
    const int blocks = vertex_blocks + (nt + kBlock - 1) / kBlock;
    std::vector<DeviationAccumulator> acc(blocks);
    parallel_chunks(blocks, o.threads, [&](int begin, int end) {
        std::vector<int> nearest;
        for (int b = begin; b < end; ++b) {
            if (b < vertex_blocks) {
                for (int v = b * kBlock; v < std::min(nv, (b + 1) * kBlock); ++v)
                    if (used[v])
                        acc[b].add(distance_to_faces(q, mesh.positions[v], nearest),
                                   mesh.positions[v]);
                continue;
            }
            const int first = (b - vertex_blocks) * kBlock;
            for (int f = first; f < std::min(nt, first + kBlock); ++f) {
                const auto& tri = mesh.triangles[f];
                for (const auto& w : bary) {
                    const Vec3 x = w[0] * mesh.positions[tri[0]] + w[1] * mesh.positions[tri[1]] +
                                   w[2] * mesh.positions[tri[2]];
                    acc[b].add(distance_to_faces(q, x, nearest), x);
                }
            }
        }
    });
    return combine(acc);
}

} // namespace

Deviation measure_brep_deviation(const Model& model, const TriangleMesh& mesh,
                                 const BRepDeviationOptions& options) {
    SEAMLESS_CHECK(!model.brep.empty(), "measure_brep_deviation needs a B-rep");
    const auto start = std::chrono::steady_clock::now();
    Deviation out;
    BRepSampled sampled;
    out.surface_to_mesh = faces_to_mesh(model, mesh, options, sampled);
    out.mesh_to_surface = mesh_to_faces(model, mesh, options, sampled);
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

} // namespace seamless
