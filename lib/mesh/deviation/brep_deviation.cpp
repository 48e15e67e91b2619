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
    // The face samples' spacing (model units).
    double reach = 0;
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

// Newton from (u, v) onto a face's surface: the distance where the foot
// lies inside the face.
double onto_face(const FaceSearch& q, int face, Vec3 x, double u, double v) {
    const SurfaceProjection p = project_to_surface(
        q.model.surfaces[q.model.brep.faces[face].surface], x, u, v, q.options.newton_iterations);
    return q.sampled.regions[face]->contains(p.u, p.v) ? p.distance : HUGE_VAL;
}

// Onto each face using an edge, from the edge sample's (u,v) on it: a point
// beside an edge whose nearest face samples all lie on other faces (a
// wall's, denser near the edge than a large plane's) would otherwise count
// its distance to the edge or to those faces, not to the face it lies on.
double beside_edge(const FaceSearch& q, const EdgeSample& s, Vec3 x) {
    double best = HUGE_VAL;
    for (const auto& [face, pcurve] : q.edge_uses[s.edge]) {
        const Vec3 uv = evaluate_point(q.model.brep.pcurves[pcurve], s.t);
        best = std::min(best, onto_face(q, face, x, uv.x, uv.y));
    }
    return best;
}

// Newton from an edge sample onto its edge's curve (within the edge's range).
double onto_curve(const FaceSearch& q, const EdgeSample& s, Vec3 x) {
    const BRepEdge& e = q.model.brep.edges[s.edge];
    return project_to_curve(q.model.brep.curves[e.curve], x, s.t, e.t0, e.t1,
                            q.options.newton_iterations)
        .distance;
}

// The faces and edges the nearest samples brought (fixed capacity: the
// options' counts are clamped to it).
struct Tried {
    static constexpr int kMost = 8;
    int faces[kMost], n_faces = 0, edges[kMost], n_edges = 0;
    bool has_face(int f) const { return std::find(faces, faces + n_faces, f) != faces + n_faces; }
    bool has_edge(int e) const { return std::find(edges, edges + n_edges, e) != edges + n_edges; }
};

// visit(sample) for the nearest to x of each run of one owner's samples
// (samples come in face and edge order, each one's contiguous).
template <class Sample, class Owner, class Visit>
void nearest_of_each(const std::vector<int>& within, const std::vector<Sample>& samples, Vec3 x,
                     Owner owner, Visit visit) {
    for (size_t i = 0; i < within.size();) {
        const int id = owner(samples[within[i]]);
        size_t nearest = i, j = i;
        double d_nearest = HUGE_VAL;
        for (; j < within.size() && owner(samples[within[j]]) == id; ++j)
            if (const Vec3 e = samples[within[j]].point - x; dot(e, e) < d_nearest)
                nearest = j, d_nearest = dot(e, e);
        i = j;
        visit(samples[within[nearest]]);
    }
}

// Every face and edge with a sample within best + reach of x that the
// nearest samples did not bring, projected on from its nearest such sample:
// a face's closest point has a sample of the face, or of its boundary, about
// a spacing away, so none closer than best is left out. Nothing past
// kWideMost spacings: the nearest samples alone then overstate by at most
// one spacing (the closest point's sample would be nearer than the
// nearest), a quarter.
void wide_search(const FaceSearch& q, Vec3 x, const Tried& tried, double& best,
                 std::vector<int>& within) {
    constexpr double kWideMost = 4;
    if (!(best <= kWideMost * q.reach)) return;
    q.face_tree.within(x, best + q.reach, within);
    nearest_of_each(
        within, q.sampled.faces, x, [](const FaceSample& s) { return s.face; },
        [&](const FaceSample& s) {
            if (!tried.has_face(s.face)) best = std::min(best, onto_face(q, s.face, x, s.u, s.v));
        });
    q.edge_tree.within(x, best + q.reach, within);
    nearest_of_each(
        within, q.sampled.edges, x, [](const EdgeSample& s) { return s.edge; },
        [&](const EdgeSample& s) {
            if (tried.has_edge(s.edge)) return;
            best = std::min({best, beside_edge(q, s, x), onto_curve(q, s, x)});
        });
}

// Distance from x to the closest point found on the faces (see the header).
double distance_to_faces(const FaceSearch& q, Vec3 x, bool wide, std::vector<int>& nearest) {
    double best = HUGE_VAL;
    Tried tried;
    const int max_tried = std::clamp(q.options.max_faces_tried, 0, Tried::kMost);
    q.face_tree.nearest(x, q.options.face_neighbours, nearest);
    for (int k = 0; k < static_cast<int>(nearest.size()); ++k) {
        const FaceSample& s = q.sampled.faces[nearest[k]];
        best = std::min(best, distance(s.point, x));
        if (!tried.has_face(s.face) && tried.n_faces < max_tried)
            tried.faces[tried.n_faces++] = s.face;
        else if (k >= q.options.newton_seeds)
            continue;
        best = std::min(best, onto_face(q, s.face, x, s.u, s.v));
    }
    q.edge_tree.nearest(x, q.options.edge_neighbours, nearest);
    for (const int i : nearest) {
        const EdgeSample& s = q.sampled.edges[i];
        const double d = distance(s.point, x);
        // Beside the edge once per edge, however far the sample.
        if (!tried.has_edge(s.edge) && tried.n_edges < Tried::kMost) {
            tried.edges[tried.n_edges++] = s.edge;
            best = std::min(best, beside_edge(q, s, x));
        }
        if (d - q.edge_piece[s.edge] >= best) continue;
        best = std::min({best, d, onto_curve(q, s, x)});
    }
    if (wide) wide_search(q, x, tried, best, nearest);
    return best;
}

// The mesh -> face sample points: every vertex a triangle uses, then each
// triangle's other barycentric points.
struct MeshPoints {
    const TriangleMesh& mesh;
    std::vector<char> used; // per vertex
    std::vector<std::array<double, 3>> bary;
    long long size() const {
        return static_cast<long long>(mesh.vertex_count()) +
               static_cast<long long>(mesh.triangle_count()) * static_cast<long long>(bary.size());
    }
    bool counts(long long i) const { return i >= mesh.vertex_count() || used[i]; }
    Vec3 operator[](long long i) const {
        const long long nv = mesh.vertex_count();
        if (i < nv) return mesh.positions[i];
        const long long nb = static_cast<long long>(bary.size());
        const auto& tri = mesh.triangles[(i - nv) / nb];
        const auto& w = bary[(i - nv) % nb];
        return w[0] * mesh.positions[tri[0]] + w[1] * mesh.positions[tri[1]] +
               w[2] * mesh.positions[tri[2]];
    }
};

MeshPoints mesh_points(const TriangleMesh& mesh, int level) {
    MeshPoints p{mesh, std::vector<char>(mesh.positions.size(), 0), barycentric_points(level)};
    for (const auto& t : mesh.triangles)
        for (const int v : t) p.used[v] = 1;
    std::erase_if(
        p.bary, [](const std::array<double, 3>& w) { return w[0] == 1 || w[1] == 1 || w[2] == 1; });
    return p;
}

// The points of `todo` (fixed blocks of it), each to the faces.
void measure_points(const FaceSearch& q, const MeshPoints& points,
                    const std::vector<long long>& todo, bool wide, std::vector<double>& d) {
    const int blocks = static_cast<int>((todo.size() + kBlock - 1) / kBlock);
    parallel_chunks(blocks, q.options.threads, [&](int begin, int end) {
        std::vector<int> nearest;
        for (size_t k = size_t(begin) * kBlock; k < std::min(todo.size(), size_t(end) * kBlock);
             ++k)
            d[todo[k]] = distance_to_faces(q, points[todo[k]], wide, nearest);
    });
}

// Mesh -> face: every point from its nearest samples, then the wide search
// for the points that may hold the maximum: those at or above half the
// maximum, again with the new maximum until it stays at or above the
// threshold (a point left out is below it, and the search only lowers a
// distance). The others' distances are their nearest samples'.
DeviationStats mesh_to_faces(const Model& model, const TriangleMesh& mesh,
                             const BRepDeviationOptions& o, const BRepSampled& s) {
    if (s.faces.empty() && s.edges.empty()) return {};
    std::vector<Vec3> positions(s.faces.size());
    for (size_t i = 0; i < s.faces.size(); ++i) positions[i] = s.faces[i].point;
    const NearestSamples face_tree(positions);
    positions.resize(s.edges.size());
    for (size_t i = 0; i < s.edges.size(); ++i) positions[i] = s.edges[i].point;
    const NearestSamples edge_tree(positions);
    std::vector<Vec3>().swap(positions);
    const FaceSearch q{model,
                       o,
                       s,
                       face_tree,
                       edge_tree,
                       edge_pieces(model.brep, s.edges),
                       edge_uses(model.brep),
                       o.relative_spacing * brep_diagonal(model)};
    const MeshPoints points = mesh_points(mesh, o.triangle_level);
    std::vector<double> d(points.size(), 0.0);
    std::vector<char> searched(points.size(), 0);
    std::vector<long long> todo;
    for (long long i = 0; i < points.size(); ++i)
        if (points.counts(i)) todo.push_back(i);
    measure_points(q, points, todo, false, d);
    for (double threshold = HUGE_VAL; o.wide_search;) {
        double most = 0;
        for (long long i = 0; i < points.size(); ++i)
            if (points.counts(i)) most = std::max(most, d[i]);
        // Past a millionth of a spacing the maximum is round-off either way.
        if (most >= threshold || most <= 1e-6 * q.reach) break;
        threshold = most / 2;
        todo.clear();
        for (long long i = 0; i < points.size(); ++i)
            if (points.counts(i) && !searched[i] && d[i] >= threshold)
                todo.push_back(i), searched[i] = 1;
        measure_points(q, points, todo, true, d);
    }
    const int blocks = static_cast<int>((points.size() + kBlock - 1) / kBlock);
    std::vector<DeviationAccumulator> acc(blocks);
    for (long long i = 0; i < points.size(); ++i)
        if (points.counts(i)) acc[i / kBlock].add(d[i], points[i]);
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
