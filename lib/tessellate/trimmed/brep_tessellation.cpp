// SPDX-License-Identifier: MIT
#include <seamless/base/error.h>
#include <seamless/base/parallel/parallel.h>
#include <seamless/base/phase_clock.h>
#include <seamless/tessellate/trimmed/bounds/brep_certification.h>
#include <seamless/tessellate/trimmed/brep_mesh.h>
#include <seamless/tessellate/trimmed/brep_tessellation.h>
#include <seamless/tessellate/trimmed/edge_discretisation.h>
#include <seamless/tessellate/trimmed/faces/constrained_triangulation.h>
#include <seamless/tessellate/trimmed/faces/face_domain.h>
#include <seamless/tessellate/trimmed/faces/face_triangulation.h>
#include <seamless/tessellate/trimmed/vertex_balls.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>

namespace seamless {

namespace {

// Rounds of re-splitting the edges of faces whose loops do not triangulate
// or whose refinement is stopped by their boundary; each halves segments.
constexpr int kResplitRounds = 8;
// OpenCASCADE's users' default angular deflection, radians.
constexpr double kDefaultAngle = 0.5;
// The default deviation as a fraction of the diagonal.
constexpr double kDefaultDeviation = 1e-3;
// Extents within 2^+-this are tessellated as they are, others rescaled.
constexpr int kScaleFreeExponent = 40;

Box3 brep_box(const Model& model) {
    Box3 box;
    for (const BRepVertex& v : model.brep.vertices) box.extend(v.point);
    for (const BSplineCurve& c : model.brep.curves)
        for (const Vec3& p : c.points) box.extend(p);
    if (box.empty() || !(norm(box.extent()) > 0)) box.extend(control_box(model));
    return box;
}

// Runs `work(i)` for every item in parallel; the first exception in item
// order is rethrown, so that which error is reported does not depend on the
// threads.
template <class Work> void for_each_item(int n, int threads, Work work) {
    std::vector<std::exception_ptr> errors(n);
    parallel_chunks(n, threads, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) try {
                work(i);
            } catch (...) {
                errors[i] = std::current_exception();
            }
    });
    for (const std::exception_ptr& e : errors)
        if (e) std::rethrow_exception(e);
}

// Each face's view of each edge, in face order.
std::vector<std::vector<EdgeOnFace>> edge_uses(const Model& model) {
    const BRep& brep = model.brep;
    std::vector<std::vector<EdgeOnFace>> uses(brep.edges.size());
    for (const BRepFace& f : brep.faces) {
        const Vec3 inward = face_uv_centre(brep, f);
        const FaceSurface surface(model.surfaces[f.surface]);
        for (const BRepLoop& loop : f.loops)
            for (const BRepCoedge& c : loop.coedges)
                uses[c.edge].push_back(
                    {surface, &brep.pcurves[c.pcurve], brep.edges[c.edge].tolerance, inward});
    }
    return uses;
}

std::vector<int> faces_of(const BRep& brep, const std::vector<int>& edges) {
    std::vector<char> hit(brep.edges.size(), 0);
    for (int e : edges) hit[e] = 1;
    std::vector<int> faces;
    for (size_t f = 0; f < brep.faces.size(); ++f)
        for (const BRepLoop& loop : brep.faces[f].loops)
            for (const BRepCoedge& c : loop.coedges)
                if (hit[c.edge] && (faces.empty() || faces.back() != static_cast<int>(f)))
                    faces.push_back(static_cast<int>(f));
    return faces;
}

struct Faces {
    std::vector<FaceMesh> meshes;
    std::vector<int> failed;
    int rounds = 0, resplit_edges = 0;
    long long face_runs = 0, judged = 0;
};

// What a re-split round halves: per edge in `edges`, the listed segments
// (halve_segments' list: empty for all of them).
struct Resplit {
    std::vector<int> edges;
    std::vector<std::vector<int>> segments; // by edge
};

// Rounds after which loops that overlap along a length are left failed:
// a two-edge loop of single chords overlaps until split, loops that run
// along each other (pcurves collapsed onto one line) overlap for good.
constexpr int kOverlapRounds = 2;
constexpr double kEven = 1.5;

// How far segment i's pcurve strays from its chord at the middle, in the
// face's scaled domain.
double sag(const BRep& brep, const std::vector<EdgePolyline>& lines, const FaceDomain& d, int i) {
    const FaceDomain::Origin& o = d.origins[i];
    const std::vector<double>& t = lines[o.edge].t;
    const Vec3 m = evaluate_point(brep.pcurves[o.pcurve], 0.5 * (t[o.segment] + t[o.segment + 1]));
    const Vec3 a = d.scaled[d.segments[i][0]], b = d.scaled[d.segments[i][1]];
    return distance(Vec3{m.x * d.su, m.y * d.sv, 0}, 0.5 * (a + b));
}

// For faces whose loops failed: of each pair of boundary segments that
// conflict, the one whose pcurve strays farther from its chord, or both
// where they stray within a factor kEven of each other. Where two loops
// touch tangentially at a vertex the chords leaving it cross however fine
// both are (the crossing is self-similar), until the one straying more is
// split alone: segments that meet are split alike only when they stray
// exactly alike. A face whose
// conflict is not between two segments (collapsed loops) gets all its
// segments halved. For faces left above the limits, their encroached
// segments.
Resplit segments_to_halve(const BRep& brep, const std::vector<EdgePolyline>& lines,
                          const std::vector<FaceMesh>& meshes, const std::vector<int>& faces,
                          bool overlaps) {
    Resplit r;
    r.segments.resize(brep.edges.size());
    std::vector<char> listed(brep.edges.size(), 0), all(brep.edges.size(), 0);
    const auto list = [&](const FaceDomain& d, int i) {
        r.segments[d.origins[i].edge].push_back(d.origins[i].segment);
        listed[d.origins[i].edge] = 1;
    };
    for (int f : faces) {
        const FaceDomain& d = meshes[f].domain;
        for (int i : meshes[f].encroached) list(d, i);
        if (!meshes[f].failed) continue;
        const auto pairs = ConstrainedTriangulation::conflicts(d.scaled, d.keys, d.segments);
        if (!overlaps &&
            std::any_of(pairs.begin(), pairs.end(),
                        [](const ConstrainedTriangulation::Conflict& c) { return c.overlap; }))
            continue;
        if (pairs.empty())
            for (const auto& o : d.origins) all[o.edge] = 1;
        for (const auto& c : pairs) {
            const double sa = sag(brep, lines, d, c.a), sb = sag(brep, lines, d, c.b);
            const auto& x = d.segments[c.a];
            const auto& y = d.segments[c.b];
            const bool meet = d.keys[x[0]] == d.keys[y[0]] || d.keys[x[0]] == d.keys[y[1]] ||
                              d.keys[x[1]] == d.keys[y[0]] || d.keys[x[1]] == d.keys[y[1]];
            const double even = meet ? 1 : kEven;
            if (!(sb > even * sa)) list(d, c.a);
            if (!(sa > even * sb)) list(d, c.b);
        }
    }
    for (size_t e = 0; e < brep.edges.size(); ++e) {
        std::vector<int>& h = r.segments[e];
        if (all[e]) h.clear();
        std::sort(h.begin(), h.end());
        h.erase(std::unique(h.begin(), h.end()), h.end());
        if (all[e] || listed[e]) r.edges.push_back(static_cast<int>(e));
    }
    return r;
}

// Triangulates every face; faces whose loops fail get the segments in
// conflict halved (for every face using their edges) and are redone with
// those faces.
Faces triangulate_faces(const Model& model, std::vector<EdgePolyline>& lines,
                        const FaceCriteria& criteria, int threads) {
    const BRep& brep = model.brep;
    Faces r;
    r.meshes.resize(brep.faces.size());
    std::vector<int> pending(brep.faces.size());
    for (size_t f = 0; f < pending.size(); ++f) pending[f] = static_cast<int>(f);
    // Per face: its last run's mesh seeds a redo (face_seeds.h), unless the
    // run failed or its interior is crowded beside the sides to halve.
    std::vector<char> seeds(brep.faces.size(), 0);
    for (;; ++r.rounds) {
        FaceCriteria c = criteria;
        c.stop_when_encroached = r.rounds < kResplitRounds;
        for_each_item(static_cast<int>(pending.size()), threads, [&](int i) {
            FaceMesh& m = r.meshes[pending[i]];
            m = seeds[pending[i]] ? triangulate_face(model, lines, pending[i], c, &m)
                                  : triangulate_face(model, lines, pending[i], c);
        });
        for (int f : pending) seeds[f] = !r.meshes[f].failed && !r.meshes[f].crowded;
        r.face_runs += static_cast<long long>(pending.size());
        for (int f : pending) r.judged += r.meshes[f].judged;
        std::vector<int> redo;
        for (int f : pending)
            if (r.meshes[f].failed || !r.meshes[f].encroached.empty()) redo.push_back(f);
        if (redo.empty() || r.rounds == kResplitRounds) break;
        const Resplit halve =
            segments_to_halve(brep, lines, r.meshes, redo, r.rounds < kOverlapRounds);
        r.resplit_edges += static_cast<int>(halve.edges.size());
        for_each_item(static_cast<int>(halve.edges.size()), threads, [&](int i) {
            const int e = halve.edges[i];
            halve_segments(brep, e, lines[e], halve.segments[e]);
            drop_points_in_vertex_balls(brep, e, lines[e], criteria.deviation);
        });
        pending = faces_of(brep, halve.edges);
        if (pending.empty()) break;
    }
    for (size_t f = 0; f < r.meshes.size(); ++f) {
        if (r.meshes[f].failed) r.failed.push_back(static_cast<int>(f));
        r.meshes[f].accepted = {}; // needed for redos only
    }
    return r;
}

void refuse_or_leave_out(const Model& model, const Faces& faces, const TessellationOptions& o,
                         BRepStats& stats) {
    for (int f : faces.failed) {
        const std::string what = "face " + model.brep.faces[f].name +
                                 ": its loops do not triangulate (boundary segments cross or "
                                 "overlap after " +
                                 std::to_string(kResplitRounds) + " re-splits)";
        if (!o.allow_holes)
            throw InputError(model.source, "brep.faces[" + std::to_string(f) + "]", what);
        stats.warnings.push_back(what + "; left out");
        ++stats.faces_left_out;
    }
}

} // namespace

void scale_lengths(Model& m, double s) {
    for (BSplineSurface& x : m.surfaces)
        for (Vec3& p : x.points) p = s * p;
    for (BSplineCurve& c : m.brep.curves)
        for (Vec3& p : c.points) p = s * p;
    for (BRepVertex& v : m.brep.vertices) v.point = s * v.point, v.tolerance *= s;
    for (BRepEdge& e : m.brep.edges) e.tolerance *= s;
}

double brep_deviation(const Model& model, const TessellationOptions& options) {
    if (options.tolerance > 0) return options.tolerance;
    if (options.eps1 > 0) return options.eps1;
    return kDefaultDeviation * norm(brep_box(model).extent());
}

namespace {

Tessellation tessellate_at_scale(const Model& model, const TessellationOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    const BRep& brep = model.brep;
    const double D = brep_deviation(model, options);
    if (!(D > 0) || !std::isfinite(D))
        throw InputError(model.source, "brep",
                         "the B-rep has zero or infinite extent: no deviation to mesh it to");
    Tessellation t;
    BRepStats& st = t.stats.brep;
    st.angle = options.angle > 0 ? options.angle : kDefaultAngle;
    const EdgeCriteria ec{D, st.angle};
    const auto uses = edge_uses(model);
    std::vector<EdgePolyline> lines(brep.edges.size());
    for_each_item(static_cast<int>(lines.size()), options.threads, [&](int e) {
        lines[e] = discretise_edge(brep, e, uses[e], ec);
        drop_points_in_vertex_balls(brep, e, lines[e], D);
    });
    st.edge_seconds = seconds_since(start);
    if (options.progress) options.progress(0.2);
    const auto faces_start = std::chrono::steady_clock::now();
    Faces faces =
        triangulate_faces(model, lines, {D, st.angle, options.max_triangles}, options.threads);
    st.face_seconds = seconds_since(faces_start);
    refuse_or_leave_out(model, faces, options, st);
    if (options.progress) options.progress(0.9);
    const auto mesh_start = std::chrono::steady_clock::now();
    t.mesh = brep_mesh(model, lines, faces.meshes);
    st.mesh_seconds = seconds_since(mesh_start);
    if (t.mesh.triangle_count() > options.max_triangles)
        throw TriangleBudgetError(model.source, "brep", options.max_triangles);

    st.faces = static_cast<int>(brep.faces.size()) - st.faces_left_out;
    st.edges = static_cast<int>(brep.edges.size());
    st.resplit_rounds = faces.rounds;
    st.resplit_edges = faces.resplit_edges;
    st.face_runs = faces.face_runs;
    st.judged_triangles = faces.judged;
    for (size_t e = 0; e < lines.size(); ++e) {
        if (!brep.edges[e].degenerate())
            st.edge_points += std::max(0, static_cast<int>(lines[e].t.size()) - 2);
        st.max_deviation = std::max(st.max_deviation, lines[e].deviation);
        st.max_edge_tolerance = std::max(st.max_edge_tolerance, brep.edges[e].tolerance);
        if (brep.edges[e].tolerance > D) ++st.edges_above_tolerance;
    }
    for (const FaceMesh& fm : faces.meshes) {
        if (fm.failed) continue;
        st.interior_points += fm.domain.size() - fm.domain.boundary_points;
        st.max_deviation = std::max(st.max_deviation, fm.deviation);
        st.above_tolerance += fm.above_tolerance;
        for (int i = 0; i < fm.domain.boundary_points; ++i)
            st.max_edge_offset = std::max(st.max_edge_offset, fm.domain.offset[i]);
    }
    if (options.certify) {
        const auto bound_start = std::chrono::steady_clock::now();
        const BRepBound bound = certify_brep(model, lines, t.mesh, options.threads);
        st.bound_triangles = bound.triangles;
        st.bound_chords = bound.chords;
        st.bound_seconds = seconds_since(bound_start);
    }
    TessellationStats& s = t.stats;
    s.surfaces = static_cast<int>(model.surfaces.size());
    s.triangles = t.mesh.triangle_count();
    s.vertices = t.mesh.vertex_count();
    s.d_max = brep_box(model).max_extent();
    s.tolerance = D;
    // Certified over the triangles and the edge chords (brep_certification.h).
    s.max_error_bound = options.certify ? std::max(st.bound_triangles, st.bound_chords)
                                        : std::numeric_limits<double>::quiet_NaN();
    s.above_tolerance = st.above_tolerance;
    s.passes = faces.rounds + 1;
    if (options.progress) options.progress(1.0);
    s.seconds = seconds_since(start);
    return t;
}

} // namespace

Tessellation tessellate_brep(const Model& model, const TessellationOptions& options) {
    // Cross products and squared distances of coordinates far from 1
    // overflow or underflow: the work is done at the power-of-two scale that
    // brings the extent near 1 (exact both ways), as on the Bezier path.
    const double extent = brep_box(model).max_extent();
    const int e = extent > 0 && std::isfinite(extent) ? std::ilogb(extent) : 0;
    Tessellation t;
    if (std::abs(e) <= kScaleFreeExponent) {
        t = tessellate_at_scale(model, options);
    } else {
        const double down = std::ldexp(1.0, -e), up = std::ldexp(1.0, e);
        Model m = model;
        scale_lengths(m, down);
        TessellationOptions o = options;
        o.tolerance *= down;
        if (o.eps1 > 0) o.eps1 *= down;
        t = tessellate_at_scale(m, o);
        for (Vec3& p : t.mesh.positions) p = up * p;
        t.stats.d_max *= up;
        t.stats.tolerance *= up;
        t.stats.brep.max_deviation *= up;
        t.stats.brep.max_edge_tolerance *= up;
        t.stats.brep.max_edge_offset *= up;
        t.stats.brep.bound_triangles *= up;
        t.stats.brep.bound_chords *= up;
        t.stats.max_error_bound *= up;
    }
    const BRepStats& st = t.stats.brep;
    // What the file claims, then what was measured: only an offset above D
    // keeps the mesh of both faces farther than D from one of them.
    const double D = t.stats.tolerance, off = st.max_edge_offset;
    if (st.edges_above_tolerance > 0 || off > D) {
        const auto g = [](double x) {
            char buf[32];
            std::snprintf(buf, sizeof buf, "%.3g", x);
            return std::string(buf);
        };
        std::string w = st.edges_above_tolerance > 0
                            ? std::to_string(st.edges_above_tolerance) +
                                  " edges claim a tolerance above the deviation " + g(D) +
                                  " (largest " + g(st.max_edge_tolerance) + "); "
                            : std::string();
        w += "the edges' curves lie up to " + g(off) +
             " off their faces (measured at the boundary points)";
        w += off > D ? ", above the deviation " + g(D) +
                           ": the deviation reached there is at least that"
                     : ", within the deviation";
        t.stats.brep.warnings.push_back(std::move(w));
    }
    return t;
}

} // namespace seamless
