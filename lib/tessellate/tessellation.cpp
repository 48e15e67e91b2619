// SPDX-License-Identifier: MIT
#include <seamless/base/error.h>
#include <seamless/base/parallel.h>
#include <seamless/tessellate/edge_graph.h>
#include <seamless/tessellate/error_bound.h>
#include <seamless/tessellate/shared_edges.h>
#include <seamless/tessellate/surface_orientation.h>
#include <seamless/tessellate/tessellation.h>

#include <algorithm>
#include <atomic>
#include <cassert>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <span>
#include <unordered_map>
#include <unordered_set>

namespace seamless {
namespace {

// A ring vertex of a subpatch: its parameters on the subpatch's patch (on the
// grid, or -1 for the coordinate along the side of a seam vertex of another
// patch, whose parameter is a projection) and its mesh vertex.
struct RingVertex {
    int s = 0, t = 0;
    double fs = 0, ft = 0;
    int foreign = -1; // index into EdgeGraph::points
    int vertex = -1;
};

// A vertex inside a side, by its line coordinate / kParamOne: a grid point or
// another line's seam vertex.
struct Inside {
    double x = 0;
    int grid = 0, foreign = -1;
};

// The subpatch's boundary, counterclockwise in (s, t) from corner (s0, t0):
// the four corners and, crack-free, every vertex a finer neighbour put on a
// side and every seam vertex of another patch lying on it (edge_graph.h).
void collect_ring(const EdgeRegistry& reg, const BoundaryMatch& match, const EdgeGraph& graph,
                  int patch, const ParamRect& r, bool crack_free, std::vector<int>& scratch,
                  std::vector<Inside>& inside, std::vector<RingVertex>& ring) {
    ring.clear();
    const int cs[4] = {r.s0, r.s1, r.s1, r.s0}, ct[4] = {r.t0, r.t0, r.t1, r.t1};
    for (int k = 0; k < 4; ++k) {
        ring.push_back({cs[k], ct[k], param_of(cs[k]), param_of(ct[k]), -1, -1});
        if (!crack_free) continue;
        const SideOnLine side = side_on_line(reg, match, patch, r, k);
        scratch.clear();
        points_inside(reg, side, scratch);
        inside.clear();
        for (int x : scratch) inside.push_back({param_of(x), x, -1});
        if (side.line >= 0 && side.line < reg.boundary_lines) {
            const std::span<const SeamPoint> seam = seam_points(graph, side.line);
            if (!seam.empty()) {
                const double a = param_of(side.a), b = param_of(side.b);
                const size_t before = inside.size();
                for (auto it =
                         std::upper_bound(seam.begin(), seam.end(), a,
                                          [](double x, const SeamPoint&p) { return x < p.x; });
                     it != seam.end() && it->x < b; ++it)
                    inside.push_back({it->x, -1, static_cast<int>(&*it - graph.points.data())});
                if (inside.size() > before && before > 0)
                    std::sort(inside.begin(), inside.end(),
                              [](const Inside& p, const Inside& q) { return p.x < q.x; });
            }
        }
        if (inside.empty()) continue;
        for (Inside& v : inside)
            if (side.reversed) v.x = 1 - v.x, v.grid = kParamOne - v.grid;
        // Sides 0, 1 run with increasing parameter, sides 2, 3 against it.
        if ((k < 2) == side.reversed) std::reverse(inside.begin(), inside.end());
        for (const Inside& v : inside) {
            const int g = v.foreign >= 0 ? -1 : v.grid;
            if (k % 2 == 0)
                ring.push_back({g, ct[k], v.x, param_of(ct[k]), v.foreign, -1});
            else
                ring.push_back({cs[k], g, param_of(cs[k]), v.x, v.foreign, -1});
        }
    }
}

} // namespace

Vec3 unit_normal(const BezierPatch& b, double s, double t, double toward_s, double toward_t) {
    SurfacePoint sp = evaluate(b, s, t);
    Vec3 n = sp.normal();
    for (double d : {1e-7, 1e-5, 1e-3, 1e-1, 0.5}) {
        if (is_finite(n) && norm(n) > 1e-12 * norm(sp.du) * norm(sp.dv) && norm(n) > 0) break;
        sp = evaluate(b, s + d * (toward_s - s), t + d * (toward_t - t));
        n = sp.normal();
    }
    return normalize(n);
}

Tessellation tessellate(const Model& model, const TessellationOptions& options) {
    return tessellate(model, bezier_patches(model), options);
}

namespace {

// A certified fan bound (error_bound.h) of an earlier pass, with the ring it
// was computed for: the bound is a function of the subpatch and its ring.
struct KnownBound {
    ParamRect rect;
    std::vector<RingPoint> ring;
    Vec3 centre;
    double bound = 0;
};

// Seconds since the previous call (or construction), for PhaseSeconds.
class Lap {
    std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();

  public:
    double operator()() {
        const auto now = std::chrono::steady_clock::now();
        const double d = std::chrono::duration<double>(now - last_).count();
        last_ = now;
        return d;
    }
};

// Dynamic scheduling on parallel_chunks (parallel.h): whichever worker is
// free takes the next block of `grain` items, so the workers finish within one
// block of each other (a fixed chunk of whole patches left one thread idle
// while the other finished it). With `order` (grain 1) the items are taken in
// that order: largest first, the last blocks are the smallest (longest
// processing time first). Items write only their own slots, so the result is
// the same for any thread count and any order.
// Subpatches per block: small against the tens of thousands of a fine
// tessellation, large against the cost of taking a block.
constexpr int kGrain = 32;

void pull_blocks(int n, int grain, int threads, const std::vector<int>* order,
                 const std::function<void(int begin, int end)>& chunk) {
    assert(!order || grain == 1);
    const int blocks = (n + grain - 1) / grain;
    std::atomic<int> next{0};
    parallel_chunks(blocks, threads, [&](int, int) {
        for (int b; (b = next.fetch_add(1, std::memory_order_relaxed)) < blocks;) {
            if (order)
                chunk((*order)[b], (*order)[b] + 1);
            else
                chunk(b * grain, std::min(n, (b + 1) * grain));
        }
    });
}

// Expected relative cost of subdividing `b` to deviation D, for the order of
// the work only: a subpatch of size h deviates about h^2 |second difference|,
// so about sqrt(M/D) splits per direction.
double patch_cost(const BezierPatch& b, double D) {
    double mss = 0, mtt = 0;
    for (int i = 0; i <= b.p; ++i)
        for (int j = 0; j <= b.q; ++j) {
            if (i >= 1 && i < b.p)
                mss = std::max(mss,
                               norm(b.point(i + 1, j) - 2.0 * b.point(i, j) + b.point(i - 1, j)));
            if (j >= 1 && j < b.q)
                mtt = std::max(mtt,
                               norm(b.point(i, j + 1) - 2.0 * b.point(i, j) + b.point(i, j - 1)));
        }
    const double cost =
        (1 + std::sqrt(b.p * (b.p - 1) * mss / D)) * (1 + std::sqrt(b.q * (b.q - 1) * mtt / D));
    return std::isfinite(cost) ? cost : 0.0;
}

bool same_ring(std::span<const RingPoint> a, std::span<const RingPoint> b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                      [](const RingPoint& p, const RingPoint& q) {
                          return p.s == q.s && p.t == q.t && p.fs == q.fs && p.ft == q.ft &&
                                 p.position == q.position;
                      });
}

// What the passes of a tolerance share, per Bezier patch (so that patches can
// be worked on in parallel): the subdivision criteria's verdicts and the
// final fans' bounds.
// One patch's split tree and leaves.
struct Part {
    PatchTrees trees;
    std::vector<Subpatch> subpatches;
    int root = -1;
};

struct PassMemo {
    std::vector<FanMemo> verdicts;
    std::vector<std::unordered_map<std::uint64_t, KnownBound>> bounds;
    // The last pass's split of each patch, and whether the next pass forces a
    // split in it (else the same verdicts give the same tree: kept).
    std::vector<Part> parts;
    std::vector<char> changed;
    bool keep = false; // fill them (only a tolerance takes more than one pass)
    PassMemo(size_t patches, bool keep)
        : verdicts(patches), bounds(patches), parts(patches), changed(patches, 1), keep(keep) {}
};

// Where each patch's nodes and leaves start in the concatenated arrays (one
// more entry: the ends).
struct PatchRanges {
    std::vector<int> node_start, leaf_start;
};

// (a) Every patch split on its own (in parallel), the trees then laid end to
// end in patch order (prefix sums, copied in parallel): the same arrays for
// any thread count.
PatchRanges subdivide_patches(const std::vector<BezierPatch>& patches,
                              const SubdivisionOptions& sub, double D, int threads, PassMemo& memo,
                              PatchTrees& trees, std::vector<Subpatch>& subpatches) {
    std::vector<Part>& parts = memo.parts;
    const int np = static_cast<int>(patches.size());
    // Patches differ in cost by ten times and more (teapot): dearest first.
    std::vector<double> cost(np);
    std::vector<int> order(np);
    for (int i = 0; i < np; ++i) cost[i] = patch_cost(patches[i], D), order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return cost[a] > cost[b]; });
    pull_blocks(np, 1, threads, &order, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) {
            if (!memo.changed[i]) continue;
            SubdivisionOptions o = sub;
            o.memo = memo.keep ? &memo.verdicts[i] : nullptr;
            parts[i] = Part{};
            parts[i].root = subdivide(patches[i], i, o, parts[i].trees, parts[i].subpatches);
        }
    });
    PatchRanges at{std::vector<int>(np + 1, 0), std::vector<int>(np + 1, 0)};
    for (int i = 0; i < np; ++i) {
        at.node_start[i + 1] = at.node_start[i] + static_cast<int>(parts[i].trees.nodes.size());
        at.leaf_start[i + 1] = at.leaf_start[i] + static_cast<int>(parts[i].subpatches.size());
        trees.depth = std::max(trees.depth, parts[i].trees.depth);
    }
    trees.nodes.resize(at.node_start[np]);
    subpatches.resize(at.leaf_start[np]);
    trees.roots.resize(np);
    parallel_chunks(np, threads, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) {
            const Part& p = parts[i];
            const int node0 = at.node_start[i], leaf0 = at.leaf_start[i];
            for (size_t j = 0; j < p.trees.nodes.size(); ++j) {
                PatchNode n = p.trees.nodes[j];
                for (int& c : n.child)
                    if (c >= 0) c += node0;
                if (n.subpatch >= 0) n.subpatch += leaf0;
                trees.nodes[node0 + j] = n;
            }
            for (size_t j = 0; j < p.subpatches.size(); ++j) {
                Subpatch sp = p.subpatches[j];
                sp.node += node0;
                subpatches[leaf0 + j] = sp;
            }
            trees.roots[i] = p.root + node0;
        }
    });
    if (!memo.keep) std::vector<Part>().swap(parts); // one pass: no copy kept
    return at;
}

// Vertices numbered as first met in subpatch order, each ring then its
// centre, as vertex_of numbers them one by one, where every vertex is its
// exact point (no straight segments: no vertex places another). In parallel:
// the keys; the first uses of each patch's interior points (they belong to
// that patch alone, and its subpatches are consecutive); the ids by a prefix
// sum over the subpatches' new vertices; the positions. In one pass: the first
// uses of the patch-boundary points, a small share of the slots.
void number_vertices(const std::vector<Subpatch>& subpatches, const std::vector<int>& leaf_start,
                     const EdgeGraph& graph, const std::vector<int>& ring_start,
                     const std::vector<Vec3>& centre_point, int threads, VertexRegistry& vr,
                     std::vector<RingVertex>& rings, std::vector<int>& centres) {
    const int count = static_cast<int>(subpatches.size());
    const int np = static_cast<int>(leaf_start.size()) - 1;
    std::vector<VertexKey> key(rings.size());
    std::vector<int> first(rings.size()); // the slot of the key's first use
    pull_blocks(count, kGrain, threads, nullptr, [&](int begin, int end) {
        for (int i = begin; i < end; ++i)
            for (int j = ring_start[i]; j < ring_start[i + 1]; ++j) {
                const RingVertex& v = rings[j];
                key[j] = canonical_key(
                    vr, v.foreign >= 0 ? graph.points[v.foreign].key
                                       : vertex_key(*vr.match, subpatches[i].patch, v.s, v.t));
            }
    });
    const auto interior = [&](int j, int patch) { return key[j].kind == 2 && key[j].id == patch; };
    pull_blocks(np, 1, threads, nullptr, [&](int begin, int end) {
        std::unordered_map<std::uint64_t, int> seen; // (s, t) -> first slot
        for (int p = begin; p < end; ++p) {
            seen.clear();
            for (int j = ring_start[leaf_start[p]]; j < ring_start[leaf_start[p + 1]]; ++j) {
                if (!interior(j, p)) continue;
                const std::uint64_t st = (static_cast<std::uint64_t>(key[j].a) << 32) |
                                         static_cast<std::uint32_t>(key[j].b);
                first[j] = seen.try_emplace(st, j).first->second;
            }
        }
    });
    std::unordered_map<VertexKey, int, VertexKeyHash> shared;
    for (int p = 0; p < np; ++p)
        for (int j = ring_start[leaf_start[p]]; j < ring_start[leaf_start[p + 1]]; ++j)
            if (!interior(j, p)) first[j] = shared.try_emplace(key[j], j).first->second;
    std::vector<int> base(count + 1, 0);
    pull_blocks(count, kGrain, threads, nullptr, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) {
            int fresh = 1; // the centre
            for (int j = ring_start[i]; j < ring_start[i + 1]; ++j) fresh += first[j] == j;
            base[i + 1] = fresh;
        }
    });
    for (int i = 0; i < count; ++i) base[i + 1] += base[i];
    vr.positions.resize(base[count]);
    vr.placed.assign(base[count], 1);
    pull_blocks(count, kGrain, threads, nullptr, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) {
            int id = base[i];
            for (int j = ring_start[i]; j < ring_start[i + 1]; ++j)
                if (first[j] == j) {
                    rings[j].vertex = id;
                    vr.positions[id++] = exact_position(*vr.patches, *vr.match, key[j]);
                }
            centres[i] = id;
            vr.positions[id] = centre_point[i];
        }
    });
    pull_blocks(count, kGrain, threads, nullptr, [&](int begin, int end) {
        for (int i = begin; i < end; ++i)
            for (int j = ring_start[i]; j < ring_start[i + 1]; ++j)
                if (first[j] != j) rings[j].vertex = rings[first[j]].vertex;
    });
}

Tessellation tessellate_pass(const Model& model, const std::vector<BezierPatch>& patches,
                             const TessellationOptions& options,
                             const std::unordered_set<std::uint64_t>& split, PassMemo& memo,
                             bool last) {
    const auto start = std::chrono::steady_clock::now();
    Lap lap;
    Tessellation out;
    TessellationStats& st = out.stats;
    PhaseSeconds& phase = st.phases;
    const Box3 box = control_box(model);
    st.d_max = box.max_extent();
    const PlanarityTolerances paper =
        options.tolerance > 0 ? PlanarityTolerances{} : paper_tolerances(st.d_max);
    st.eps1 = options.eps1 >= 0 ? options.eps1 : paper.eps1;
    st.eps2 = options.eps2 >= 0 ? options.eps2 : paper.eps2;
    st.tolerance = std::max(options.tolerance, 0.0);
    st.surfaces = static_cast<int>(model.surfaces.size());
    st.patches = static_cast<int>(patches.size());
    const double scale =
        box.empty() ? 0.0
                    : std::max({std::abs(box.lo.x), std::abs(box.lo.y), std::abs(box.lo.z),
                                std::abs(box.hi.x), std::abs(box.hi.y), std::abs(box.hi.z)});

    // (a) Split trees by the planarity test alone (section 6).
    constexpr double kOff = std::numeric_limits<double>::infinity();
    SubdivisionOptions sub;
    sub.eps1 = st.eps1 > 0 || options.eps1 >= 0 ? st.eps1 : kOff;
    sub.eps2 = st.eps2 > 0 || options.eps2 >= 0 ? st.eps2 : kOff;
    sub.tolerance = st.tolerance;
    sub.angle = options.angle;
    sub.max_depth = options.max_depth;
    sub.split = &split;
    const double D = st.tolerance > 0 ? st.tolerance : st.eps1 > 0 ? st.eps1 : 1e-3 * st.d_max;
    const PatchRanges ranges =
        subdivide_patches(patches, sub, D, options.threads, memo, out.trees, out.subpatches);
    phase.subdivision += lap();

    // (b) Shared boundaries, poles and welded corners; (c) the subpatch sides on every line.
    // Shared boundaries agree to the seam tolerance, and at least to the
    // rounding of knot insertion, which scales with the coordinates'
    // magnitude, not with d_max: a model far from the origin needs the larger.
    st.seam_tolerance =
        std::max(options.seam_tolerance >= 0 ? options.seam_tolerance : 1e-9 * st.d_max,
                 64 * std::numeric_limits<double>::epsilon() * scale);
    const BoundaryMatch match = match_boundaries(patches, st.seam_tolerance);
    st.shared_edges = match.shared_edges;
    st.collapsed_edges = match.collapsed_edges;
    const EdgeRegistry reg = build_edge_registry(match, out.subpatches, options.threads);
    // (c') The rest of the boundaries by geometry: one edge graph of the model.
    const EdgeGraph graph =
        options.crack_free ? build_edge_graph(patches, match, reg, st.seam_tolerance) : EdgeGraph{};
    st.seams = graph.seams;
    st.seam_vertices = graph.seam_vertices;
    VertexRegistry vr;
    vr.patches = &patches;
    vr.match = &match;
    vr.edges = &reg;
    vr.alias = &graph.alias;
    vr.crack_free = options.crack_free;
    // With a tolerance every vertex is its exact surface point: a corner a
    // coarser neighbour's straight segment held off the surface by its sagitta
    // lifted the finer side's bound above the tolerance across patch edges,
    // where phi may not move it, and halving either side did not end it (the
    // sides stayed a level apart pass after pass). The fans on both sides run
    // over every vertex on their sides, by index, so no crack opens.
    vr.straight_segments = st.tolerance <= 0;
    phase.boundaries += lap();

    // (d) Fans: each planar subpatch from its centre over its ring.
    TriangleMesh& mesh = out.mesh;
    for (const BSplineSurface& s : model.surfaces) mesh.surface_names.push_back(s.name);
    // (d0) Each subpatch's ring and centre point on its own, in parallel.
    const size_t count = out.subpatches.size();
    std::vector<std::vector<RingVertex>> ring_of(count);
    std::vector<Vec3> centre_point(count);
    pull_blocks(static_cast<int>(count), kGrain, options.threads, nullptr, [&](int begin, int end) {
        std::vector<int> scratch;
        std::vector<Inside> inside;
        for (int i = begin; i < end; ++i) {
            const Subpatch& sp = out.subpatches[i];
            const ParamRect& r = sp.rect;
            collect_ring(reg, match, graph, sp.patch, r, options.crack_free, scratch, inside,
                         ring_of[i]);
            const double sc = 0.5 * (param_of(r.s0) + param_of(r.s1));
            const double tc = 0.5 * (param_of(r.t0) + param_of(r.t1));
            centre_point[i] = evaluate(patches[sp.patch], sc, tc).point;
        }
    });
    phase.rings += lap();
    // (d1) Their vertices, numbered as first met in subpatch order (each ring,
    // then its centre). The rings laid end to end by a prefix sum.
    std::vector<int> ring_start(count + 1, 0), centres(count);
    for (size_t i = 0; i < count; ++i)
        ring_start[i + 1] = ring_start[i] + static_cast<int>(ring_of[i].size());
    std::vector<RingVertex> rings(ring_start[count]);
    pull_blocks(static_cast<int>(count), kGrain, options.threads, nullptr, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) {
            std::copy(ring_of[i].begin(), ring_of[i].end(), rings.begin() + ring_start[i]);
            std::vector<RingVertex>().swap(ring_of[i]);
        }
    });
    if (vr.crack_free && vr.straight_segments) {
        // A vertex on a straight segment places the segment's ends first:
        // one by one.
        // About three vertices per subpatch: reserving avoids the copies of
        // growing these arrays.
        vr.positions.reserve(3 * count);
        vr.placed.reserve(3 * count);
        vr.index.reserve(2 * count);
        for (size_t i = 0; i < count; ++i) {
            const Subpatch& sp = out.subpatches[i];
            for (int j = ring_start[i]; j < ring_start[i + 1]; ++j) {
                RingVertex& v = rings[j];
                v.vertex = v.foreign >= 0 ? vertex_of(vr, graph.points[v.foreign].key)
                                          : vertex_at(vr, sp.patch, v.s, v.t);
            }
            centres[i] = static_cast<int>(vr.positions.size());
            vr.positions.push_back(centre_point[i]);
            vr.placed.push_back(1);
        }
    } else {
        number_vertices(out.subpatches, ranges.leaf_start, graph, ring_start, centre_point,
                        options.threads, vr, rings, centres);
    }
    phase.numbering += lap();

    // (d2) Each subpatch's certified bound on its own, in parallel.
    std::vector<char> fresh(count, 0);
    const bool certify = options.certify || st.tolerance > 0;
    if (!certify) {
        for (Subpatch& sp : out.subpatches)
            sp.error_bound = std::numeric_limits<double>::quiet_NaN();
        st.max_error_bound = std::numeric_limits<double>::quiet_NaN();
    }
    const int certified = certify ? static_cast<int>(count) : 0;
    pull_blocks(certified, kGrain, options.threads, nullptr, [&](int begin, int end) {
        std::vector<RingPoint> fan;
        for (int i = begin; i < end; ++i) {
            Subpatch& sp = out.subpatches[i];
            const Vec3 centre = vr.positions[centres[i]];
            // Certified two-way distance of the subpatch and its fan (error_bound.h).
            fan.clear();
            for (int j = ring_start[i]; j < ring_start[i + 1]; ++j) {
                const RingVertex& v = rings[j];
                fan.push_back({v.s, v.t, vr.positions[v.vertex], v.fs, v.ft});
            }
            const auto& known = memo.bounds[sp.patch];
            const auto it = known.find(subpatch_key(sp.patch, sp.rect));
            if (it != known.end() && it->second.rect == sp.rect && it->second.centre == centre &&
                same_ring(it->second.ring, fan)) {
                sp.error_bound = it->second.bound;
            } else {
                sp.error_bound = certified_fan_bound(patches[sp.patch], sp.rect, sp.depth, centre,
                                                     fan, scale, st.tolerance);
                fresh[i] = 1;
            }
        }
    });
    for (size_t i = 0; certify && i < count; ++i) {
        const Subpatch& sp = out.subpatches[i];
        if (st.tolerance > 0 && sp.error_bound > st.tolerance) ++st.above_tolerance;
        st.max_error_bound = std::max(st.max_error_bound, sp.error_bound);
    }
    // The fresh bounds kept for the next pass: each patch's map on its own.
    const int np = static_cast<int>(patches.size());
    parallel_chunks(certify && memo.keep ? np : 0, options.threads, [&](int begin, int end) {
        for (int p = begin; p < end; ++p)
            for (int i = ranges.leaf_start[p]; i < ranges.leaf_start[p + 1]; ++i) {
                if (!fresh[i]) continue;
                const Subpatch& sp = out.subpatches[i];
                KnownBound& k = memo.bounds[p][subpatch_key(sp.patch, sp.rect)];
                k.ring.clear();
                for (int j = ring_start[i]; j < ring_start[i + 1]; ++j) {
                    const RingVertex& v = rings[j];
                    k.ring.push_back({v.s, v.t, vr.positions[v.vertex], v.fs, v.ft});
                }
                k.rect = sp.rect;
                k.centre = vr.positions[centres[i]];
                k.bound = sp.error_bound;
            }
    });
    phase.bounds += lap();
    // Another pass will follow: the mesh of this one is not needed.
    if (!last && st.above_tolerance > 0) return out;

    // (d3) Normals at the fans' vertices, in parallel.
    std::vector<Vec3> ring_normals(rings.size()), centre_normals(count);
    pull_blocks(static_cast<int>(count), kGrain, options.threads, nullptr, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) {
            const Subpatch& sp = out.subpatches[i];
            const BezierPatch& b = patches[sp.patch];
            const double sc = 0.5 * (param_of(sp.rect.s0) + param_of(sp.rect.s1));
            const double tc = 0.5 * (param_of(sp.rect.t0) + param_of(sp.rect.t1));
            centre_normals[i] = unit_normal(b, sc, tc, sc, tc);
            for (int j = ring_start[i]; j < ring_start[i + 1]; ++j)
                ring_normals[j] = unit_normal(b, rings[j].fs, rings[j].ft, sc, tc);
        }
    });
    phase.normals += lap();

    // (d4) Fan triangles in subpatch order; none where two ring vertices are
    // one (a pole). Counted per subpatch, placed by prefix sums, written in
    // parallel: the same arrays for any thread count.
    pull_blocks(static_cast<int>(count), kGrain, options.threads, nullptr, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) {
            const int first = ring_start[i], n = ring_start[i + 1] - first;
            int c = 0;
            for (int k = 0; k < n; ++k)
                c += rings[first + k].vertex != rings[first + (k + 1) % n].vertex;
            out.subpatches[i].triangle_count = c;
        }
    });
    std::vector<int> fan_node(count + 1);
    int triangles = 0;
    fan_node[0] = static_cast<int>(out.trees.nodes.size());
    for (size_t i = 0; i < count; ++i) {
        Subpatch& sp = out.subpatches[i];
        sp.first_triangle = triangles;
        triangles += sp.triangle_count;
        fan_node[i + 1] = fan_node[i] + attached_nodes(sp.triangle_count);
        st.max_depth = std::max(st.max_depth, sp.depth);
        if (!sp.planar) ++st.nonplanar_subpatches;
    }
    mesh.triangles.resize(triangles);
    mesh.triangle_surface.resize(triangles);
    mesh.corner_normals.resize(triangles);
    mesh.corner_uvs.resize(triangles);
    out.trees.nodes.resize(fan_node[count]);
    std::vector<int> added(count);
    pull_blocks(static_cast<int>(count), kGrain, options.threads, nullptr, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) {
            const Subpatch& sp = out.subpatches[i];
            const BezierPatch& b = patches[sp.patch];
            const ParamRect& r = sp.rect;
            const double sc = 0.5 * (param_of(r.s0) + param_of(r.s1));
            const double tc = 0.5 * (param_of(r.t0) + param_of(r.t1));
            const int first = ring_start[i], n = ring_start[i + 1] - first;
            int f = sp.first_triangle;
            for (int k = 0; k < n; ++k) {
                const RingVertex &a = rings[first + k], &c = rings[first + (k + 1) % n];
                if (a.vertex == c.vertex) continue;
                mesh.triangles[f] = {centres[i], a.vertex, c.vertex};
                mesh.triangle_surface[f] = b.surface;
                mesh.corner_normals[f] = {centre_normals[i], ring_normals[first + k],
                                          ring_normals[first + (k + 1) % n]};
                mesh.corner_uvs[f] = {std::array<double, 2>{b.u_at(sc), b.v_at(tc)},
                                      std::array<double, 2>{b.u_at(a.fs), b.v_at(a.ft)},
                                      std::array<double, 2>{b.u_at(c.fs), b.v_at(c.ft)}};
                ++f;
            }
            // Proposition 11, remark 2: the triangles become the leaves below the subpatch.
            added[i] = attach_triangles_at(out.trees, sp.node, sp.first_triangle, sp.triangle_count,
                                           fan_node[i]);
        }
    });
    for (size_t i = 0; i < count; ++i)
        out.trees.depth = std::max(out.trees.depth, out.subpatches[i].depth + added[i]);
    mesh.positions = std::move(vr.positions);
    // Hulls bottom-up: each fan's subtree, then each patch's nodes above them.
    const auto triangle_box = [&mesh](int f) {
        Box3 bb;
        for (int v : mesh.triangles[f]) bb.extend(mesh.positions[v]);
        return bb;
    };
    pull_blocks(static_cast<int>(count), kGrain, options.threads, nullptr, [&](int begin, int end) {
        for (int i = begin; i < end; ++i)
            update_triangle_hulls(out.trees, fan_node[i], fan_node[i + 1], triangle_box);
    });
    parallel_chunks(np, options.threads, [&](int begin, int end) {
        for (int p = begin; p < end; ++p)
            update_triangle_hulls(out.trees, ranges.node_start[p], ranges.node_start[p + 1],
                                  triangle_box);
    });
    phase.fans += lap();

    // At unit scale: the signed volume of a closed component stays finite.
    if (options.orient_surfaces)
        st.flipped_surfaces = orient_surfaces(mesh, options.threads).flipped_surfaces;
    phase.orientation += lap();

    st.subpatches = static_cast<int>(out.subpatches.size());
    st.triangles = mesh.triangle_count();
    st.vertices = mesh.vertex_count();
    st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

void add(PhaseSeconds& sum, const PhaseSeconds& p) {
    sum.subdivision += p.subdivision;
    sum.boundaries += p.boundaries;
    sum.rings += p.rings;
    sum.numbering += p.numbering;
    sum.bounds += p.bounds;
    sum.normals += p.normals;
    sum.fans += p.fans;
    sum.orientation += p.orientation;
}

// With a tolerance: a subpatch accepted by its four-triangle bound can end
// above the tolerance once neighbours add vertices to its sides (its final
// fan and phi differ from the four triangles'); such subpatches are split in
// another pass (rarely more than one).
Tessellation tessellate_at_unit_scale(const Model& model, const std::vector<BezierPatch>& patches,
                                      const TessellationOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    std::unordered_set<std::uint64_t> split;
    PassMemo memo(patches.size(), options.tolerance > 0);
    Tessellation t;
    PhaseSeconds phases;
    constexpr int kPasses = 5;
    int pass = 0;
    for (;; ++pass) {
        const bool last = options.tolerance <= 0 || pass == kPasses - 1;
        t = tessellate_pass(model, patches, options, split, memo, last);
        add(phases, t.stats.phases);
        if (last || t.stats.above_tolerance == 0) break;
        std::fill(memo.changed.begin(), memo.changed.end(), 0);
        for (const Subpatch& sp : t.subpatches)
            if (sp.error_bound > t.stats.tolerance && sp.depth < options.max_depth) {
                split.insert(subpatch_key(sp.patch, sp.rect));
                memo.changed[sp.patch] = 1;
            }
    }
    t.stats.passes = pass + 1;
    t.stats.phases = phases;
    t.stats.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return t;
}

} // namespace

Tessellation tessellate(const Model& model, const std::vector<BezierPatch>& patches,
                        const TessellationOptions& options) {
    // Stiff cases: huge and tiny coordinates. Cross products and squared
    // distances of coordinates far from 1 overflow or underflow (a plane
    // through three points of size 1e-151 has a normal of length 0 in
    // doubles), so the work is done at the power-of-two scale that brings
    // d_max into [1, 2): exact both ways, the result is the same mesh, scaled.
    const Box3 box = control_box(model);
    const double dm = box.max_extent();
    if (!box.empty()) {
        // Tolerances are fractions of d_max: a model of zero extent (all
        // control points equal) would never be planar within 0 and split every
        // patch to max_depth; one whose extent is below the rounding of its
        // coordinates would do the same. Both get an answer at once.
        const double magnitude =
            std::max({std::abs(box.lo.x), std::abs(box.lo.y), std::abs(box.lo.z),
                      std::abs(box.hi.x), std::abs(box.hi.y), std::abs(box.hi.z)});
        if (!(dm > 0))
            throw InputError(model.source, "surfaces",
                             "every control point is the same point (zero extent): nothing to "
                             "tessellate");
        if (!std::isfinite(dm))
            throw InputError(model.source, "surfaces",
                             "extent overflows a double (coordinates beyond the limit)");
        if (dm < 0x1p-30 * magnitude)
            throw InputError(model.source, "surfaces",
                             "extent d_max is below 2^-30 of the coordinates' magnitude: "
                             "tolerances would be below their rounding (move the model "
                             "nearer the origin)");
    }
    const int e = dm > 0 && std::isfinite(dm) ? std::ilogb(dm) : 0;
    if (e == 0) return tessellate_at_unit_scale(model, patches, options);
    const auto start = std::chrono::steady_clock::now();
    Lap lap;
    const double down = std::ldexp(1.0, -e), up = std::ldexp(1.0, e);
    Model m = model;
    for (BSplineSurface& s : m.surfaces)
        for (Vec3& p : s.points) p = down * p;
    std::vector<BezierPatch> ps = patches;
    parallel_chunks(static_cast<int>(ps.size()), options.threads, [&](int begin, int end) {
        for (int i = begin; i < end; ++i)
            for (HPoint& h : ps[i].cp) h = {down * h.x, down * h.y, down * h.z, h.w};
    });
    TessellationOptions o = options;
    if (o.eps1 >= 0) o.eps1 *= down;
    if (o.eps2 >= 0) o.eps2 *= down;
    if (o.seam_tolerance >= 0) o.seam_tolerance *= down;
    o.tolerance *= down;
    const double scale_in = lap();
    Tessellation t = tessellate_at_unit_scale(m, ps, o);
    lap();
    auto grow = [&](Box3& b) {
        if (!b.empty()) b = {up * b.lo, up * b.hi};
    };
    parallel_chunks(t.mesh.vertex_count(), options.threads, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) t.mesh.positions[i] = up * t.mesh.positions[i];
    });
    parallel_chunks(static_cast<int>(t.trees.nodes.size()), options.threads,
                    [&](int begin, int end) {
                        for (int i = begin; i < end; ++i) {
                            grow(t.trees.nodes[i].control_hull);
                            grow(t.trees.nodes[i].triangle_hull);
                        }
                    });
    parallel_chunks(static_cast<int>(t.subpatches.size()), options.threads,
                    [&](int begin, int end) {
                        for (int i = begin; i < end; ++i) {
                            Subpatch& sp = t.subpatches[i];
                            sp.fan_error *= up;
                            sp.error_bound *= up;
                            sp.centre = up * sp.centre;
                            for (Vec3& c : sp.corners) c = up * c;
                        }
                    });
    t.stats.d_max *= up;
    t.stats.eps1 *= up;
    t.stats.eps2 *= up;
    t.stats.seam_tolerance *= up;
    t.stats.tolerance = options.tolerance > 0 ? options.tolerance : 0.0;
    t.stats.max_error_bound *= up;
    t.stats.phases.scaling = scale_in + lap();
    t.stats.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return t;
}

} // namespace seamless
