// SPDX-License-Identifier: MIT
#include <seamless/base/error.h>
#include <seamless/base/parallel/parallel.h>
#include <seamless/tessellate/fans/fan_triangles.h>
#include <seamless/tessellate/fans/vertex_numbering.h>
#include <seamless/tessellate/seams/surface_orientation.h>
#include <seamless/tessellate/tessellation_pass.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace seamless {

namespace {

// Per patch: whether its rings are the previous pass's, where `changed` says
// which patches were split again: neither it nor a patch across one of its
// edges was (its sides' lines hold the same segments).
std::vector<char> unchanged_rings(const BoundaryMatch& match, const std::vector<char>& changed) {
    const int np = static_cast<int>(changed.size());
    std::vector<char> dirty(match.group_ref.size(), 0), same(np, 0);
    for (int pe = 0; pe < 4 * np; ++pe)
        if (match.edge_group[pe] >= 0 && changed[pe / 4]) dirty[match.edge_group[pe]] = 1;
    for (int p = 0; p < np; ++p) {
        same[p] = !changed[p];
        for (int e = 0; e < 4; ++e) {
            const int g = match.edge_group[4 * p + e];
            if (g >= 0 && dirty[g]) same[p] = 0;
        }
    }
    return same;
}

// The largest magnitude of the box's coordinates (0 when it is empty).
double magnitude(const Box3& box) {
    return box.empty() ? 0.0
                       : std::max({std::abs(box.lo.x), std::abs(box.lo.y), std::abs(box.lo.z),
                                   std::abs(box.hi.x), std::abs(box.hi.y), std::abs(box.hi.z)});
}

// What every pass reports alike: d_max, the planarity tolerances (the paper's
// without a tolerance), the tolerance and the counts of the input.
TessellationStats pass_stats(const Model& model, const std::vector<BezierPatch>& patches,
                             const TessellationOptions& options) {
    TessellationStats st;
    st.d_max = control_box(model).max_extent();
    const PlanarityTolerances paper =
        options.tolerance > 0 ? PlanarityTolerances{} : paper_tolerances(st.d_max);
    st.eps1 = options.eps1 >= 0 ? options.eps1 : paper.eps1;
    st.eps2 = options.eps2 >= 0 ? options.eps2 : paper.eps2;
    st.tolerance = std::max(options.tolerance, 0.0);
    st.surfaces = static_cast<int>(model.surfaces.size());
    st.patches = static_cast<int>(patches.size());
    return st;
}

// Step (a)'s criteria: the planarity tolerances (off when 0 and not asked
// for), the tolerance, the angle and max_depth.
SubdivisionOptions subdivision_options(const TessellationStats& st,
                                       const TessellationOptions& options) {
    constexpr double kOff = std::numeric_limits<double>::infinity();
    SubdivisionOptions sub;
    sub.eps1 = st.eps1 > 0 || options.eps1 >= 0 ? st.eps1 : kOff;
    sub.eps2 = st.eps2 > 0 || options.eps2 >= 0 ? st.eps2 : kOff;
    sub.tolerance = st.tolerance;
    sub.angle = options.angle;
    sub.max_depth = options.max_depth;
    return sub;
}

// The deviation the patches' costs are ordered by (patch_cost).
double cost_deviation(const TessellationStats& st) {
    return st.tolerance > 0 ? st.tolerance : st.eps1 > 0 ? st.eps1 : 1e-3 * st.d_max;
}

} // namespace

void refuse_triangle_budget(const Model& model, const TessellationOptions& options) {
    throw TriangleBudgetError(model.source, options.tolerance > 0 ? "tolerance" : "eps1, eps2",
                              options.max_triangles);
}

TessellationPass::TessellationPass(const Model& model, const std::vector<BezierPatch>& patches,
                                   const TessellationOptions& options, double hull_scale)
    : model_(model), patches_(patches), options_(options), hull_scale_(hull_scale),
      stats_(pass_stats(model, patches, options)), scale_(magnitude(control_box(model))),
      keep_(options.tolerance > 0),
      subdivision_(patches, subdivision_options(stats_, options), cost_deviation(stats_),
                   options.threads,
                   std::max<std::int64_t>(options.max_triangles, 0) / (keep_ ? 2 : 4), keep_),
      fans_(patches, scale_, stats_.tolerance, options.angle, options.threads),
      changed_(patches.size(), 1), progress_(options.progress, 0) {
    // Shared boundaries agree to the seam tolerance, and at least to the
    // rounding of knot insertion, which scales with the coordinates'
    // magnitude, not with d_max: a model far from the origin needs the larger.
    seam_tolerance_ =
        std::max(options.seam_tolerance >= 0 ? options.seam_tolerance : 1e-9 * stats_.d_max,
                 64 * std::numeric_limits<double>::epsilon() * scale_);
}

Tessellation TessellationPass::run(int pass, bool last) {
    progress_ = PassProgress(options_.progress, pass);
    start_ = std::chrono::steady_clock::now();
    clock_ = Lap();
    out_ = Tessellation();
    out_.stats = stats_;
    const PatchRanges ranges = subdivide();
    Boundaries boundaries = find_boundaries();
    Rings rings = collect_rings(ranges, boundaries);
    VertexRegistry vertices = number_vertices(ranges, boundaries, rings);
    certify(ranges, boundaries, rings, vertices, last);
    // Another pass will follow: the mesh of this one is not needed.
    if (!last && out_.stats.above_tolerance > 0) {
        keep_for_next_pass(ranges, boundaries, rings, vertices);
        return std::move(out_);
    }
    release_before_mesh(boundaries, rings);
    build_mesh(ranges, rings, vertices);
    TessellationStats& st = out_.stats;
    st.subpatches = static_cast<int>(out_.subpatches.size());
    st.triangles = out_.mesh.triangle_count();
    st.vertices = out_.mesh.vertex_count();
    st.seconds = seconds_since(start_);
    return std::move(out_);
}

void TessellationPass::lap(double& seconds, double fraction) {
    seconds += clock_();
    progress_.at(fraction);
}

// (a) Split trees by the planarity test alone (section 6).
PatchRanges TessellationPass::subdivide() {
    PatchRanges ranges =
        subdivision_.subdivide(changed_, split_, options_.patch_trees ? &out_.trees : nullptr,
                               out_.subpatches, &progress_);
    if (ranges.over_budget) refuse_triangle_budget(model_, options_);
    lap(out_.stats.phases.subdivision, PassProgress::kSubdivided);
    return ranges;
}

// (b) Shared boundaries, poles and welded corners; (c) the subpatch sides on
// every line; (c') the rest of the boundaries by geometry: one edge graph of
// the model.
Boundaries TessellationPass::find_boundaries() {
    TessellationStats& st = out_.stats;
    st.seam_tolerance = seam_tolerance_;
    if (!matched_) {
        match_ = match_boundaries(patches_, seam_tolerance_);
        matched_ = true;
    }
    st.shared_edges = match_.shared_edges;
    st.collapsed_edges = match_.collapsed_edges;
    // A patch not split again keeps its sides and interior lines (the
    // previous pass's registry).
    const int np = static_cast<int>(patches_.size());
    std::vector<char> kept(np, 0);
    PreviousRegistry previous_registry;
    if (!previous_.leaf_start.empty()) {
        for (int p = 0; p < np; ++p) kept[p] = !changed_[p];
        previous_registry = {&previous_.registry, &previous_.leaf_start, &kept};
    }
    Boundaries b;
    b.registry = build_edge_registry(match_, out_.subpatches, options_.threads, previous_registry);
    // The previous pass's registry is copied from by now: freed, so that the
    // rings and the numbering refill its pages.
    previous_.registry = EdgeRegistry();
    if (options_.crack_free)
        b.graph = build_edge_graph(patches_, match_, b.registry, seam_tolerance_);
    st.seams = b.graph.seams;
    st.seam_vertices = b.graph.seam_vertices;
    lap(st.phases.boundaries, PassProgress::kBoundaries);
    return b;
}

PreviousRings TessellationPass::previous_rings(const PatchRanges& ranges,
                                               const Rings& rings) const {
    if (!rings.previous) return {};
    return {&previous_.rings, &previous_.leaf_start, &ranges.leaf_start, &rings.same,
            &previous_.positions};
}

// (d) Fans: each planar subpatch from its centre over its ring. (d0) Each
// subpatch's ring and centre point on its own, in parallel. A patch's rings
// are the previous pass's when neither it nor a patch across its edges was
// split again (its sides' lines hold the same segments), and no seam vertices
// or aliases are involved; so are their vertices' positions (each the exact
// point of its key).
Rings TessellationPass::collect_rings(const PatchRanges& ranges, const Boundaries& boundaries) {
    const EdgeGraph& graph = boundaries.graph;
    Rings r;
    if (previous_.rings_kept && graph.points.empty() && graph.alias.empty()) {
        r.same = unchanged_rings(match_, changed_);
        r.previous = true;
    }
    r.rings =
        seamless::collect_rings(patches_, out_.subpatches, boundaries.registry, graph,
                                options_.crack_free, options_.threads, previous_rings(ranges, r));
    lap(out_.stats.phases.rings, PassProgress::kRings);
    return r;
}

// (d1) The rings' vertices, numbered as first met in subpatch order (each
// ring, then its centre).
VertexRegistry TessellationPass::number_vertices(const PatchRanges& ranges,
                                                 const Boundaries& boundaries, Rings& rings) {
    VertexRegistry vr;
    vr.patches = &patches_;
    vr.match = &match_;
    vr.edges = &boundaries.registry;
    vr.alias = &boundaries.graph.alias;
    vr.crack_free = options_.crack_free;
    // With a tolerance every vertex is its exact surface point: a corner a
    // coarser neighbour's straight segment held off the surface by its sagitta
    // lifted the finer side's bound above the tolerance across patch edges,
    // where phi may not move it, and halving either side did not end it (the
    // sides stayed a level apart pass after pass). The fans on both sides run
    // over every vertex on their sides, by index, so no crack opens.
    vr.straight_segments = out_.stats.tolerance <= 0;
    seamless::number_vertices(out_.subpatches, ranges.leaf_start, boundaries.graph,
                              options_.threads, vr, rings.rings, previous_rings(ranges, rings));
    lap(out_.stats.phases.numbering, PassProgress::kNumbered);
    return vr;
}

// (d2) Each subpatch's certified bound on its own, in parallel.
void TessellationPass::certify(const PatchRanges& ranges, const Boundaries& boundaries,
                               const Rings& rings, const VertexRegistry& vertices, bool last) {
    TessellationStats& st = out_.stats;
    if (!options_.certify && st.tolerance <= 0) {
        for (Subpatch& sp : out_.subpatches)
            sp.error_bound = std::numeric_limits<double>::quiet_NaN();
        st.max_error_bound = std::numeric_limits<double>::quiet_NaN();
        lap(st.phases.bounds, PassProgress::kBounded);
        return;
    }
    const std::vector<char> fresh =
        fans_.certify(rings.rings, vertices.positions, previous_rings(ranges, rings).same,
                      out_.subpatches, &progress_);
    std::vector<char> next_changed(patches_.size(), 0);
    for (const Subpatch& sp : out_.subpatches) {
        if (st.tolerance > 0 && sp.error_bound > st.tolerance) ++st.above_tolerance;
        st.max_error_bound = std::max(st.max_error_bound, sp.error_bound);
        next_changed[sp.patch] |= splits_again(sp, st.tolerance, options_.max_depth);
    }
    // For the next pass, if one follows: the rings of patches it may compare
    // rings of (all where this pass's rings are not kept).
    if (keep_ && !last && st.above_tolerance > 0) {
        const bool kept = boundaries.graph.points.empty() && boundaries.graph.alias.empty();
        std::vector<char> compared;
        if (kept) {
            compared = unchanged_rings(match_, next_changed);
            for (char& c : compared) c = !c;
        }
        fans_.keep(rings.rings, vertices.positions, ranges.leaf_start, fresh,
                   kept ? &compared : nullptr, out_.subpatches);
    }
    lap(st.phases.bounds, PassProgress::kBounded);
}

void TessellationPass::keep_for_next_pass(const PatchRanges& ranges, Boundaries& boundaries,
                                          Rings& rings, VertexRegistry& vertices) {
    if (!keep_) return;
    previous_.leaf_start = ranges.leaf_start;
    previous_.registry = std::move(boundaries.registry);
    previous_.rings_kept = boundaries.graph.points.empty() && boundaries.graph.alias.empty();
    if (previous_.rings_kept) {
        previous_.rings = std::move(rings.rings);
        previous_.positions = std::move(vertices.positions);
    }
}

// What only the numbering and another pass need: the previous pass's
// registry, rings and positions (copied from by now), this pass's registry and
// the rings' keys, and the shared per-patch tables and trees (freed patch by
// patch in parallel rather than on the calling thread). Freed before the mesh
// is built, so that its normals, fans and orientation refill these pages
// instead of faulting in fresh ones.
void TessellationPass::release_before_mesh(Boundaries& boundaries, Rings& rings) {
    previous_.registry = EdgeRegistry();
    previous_.rings = SubpatchRings();
    std::vector<Vec3>().swap(previous_.positions);
    previous_.rings_kept = false;
    boundaries.registry = EdgeRegistry();
    std::vector<VertexKey>().swap(rings.rings.keys);
    parallel_chunks(subdivision_.kept_patches(), options_.threads, [&](int begin, int end) {
        for (int p = begin; p < end; ++p) {
            subdivision_.release(p);
            fans_.release(p);
        }
    });
}

// (d3) Normals at the fans' vertices, in parallel; (d4) fan triangles in
// subpatch order, their patch-tree leaves and hulls; then each surface turned
// to face outward, at unit scale (the signed volume of a closed component
// stays finite).
void TessellationPass::build_mesh(const PatchRanges& ranges, const Rings& rings,
                                  VertexRegistry& vertices) {
    PhaseSeconds& phase = out_.stats.phases;
    for (const BSplineSurface& s : model_.surfaces) out_.mesh.surface_names.push_back(s.name);
    const FanNormals normals =
        fan_normals(patches_, out_.subpatches, ranges.leaf_start, rings.rings, options_.threads);
    lap(phase.normals, PassProgress::kNormals);
    const FanSources fans{.patches = &patches_,
                          .rings = &rings.rings,
                          .normals = &normals,
                          .node_start = options_.patch_trees ? &ranges.node_start : nullptr,
                          .hull_scale = hull_scale_,
                          .threads = options_.threads};
    write_fans(fans, std::move(vertices.positions), out_);
    lap(phase.fans, PassProgress::kFans);
    if (options_.orient_surfaces)
        out_.stats.flipped_surfaces = orient_surfaces(out_.mesh, options_.threads).flipped_surfaces;
    lap(phase.orientation, 1.0);
}

void TessellationPass::split_again(Tessellation& t) {
    std::fill(changed_.begin(), changed_.end(), 0);
    for (const Subpatch& sp : t.subpatches)
        if (splits_again(sp, t.stats.tolerance, options_.max_depth)) {
            split_.insert(subpatch_key(sp.patch, sp.rect));
            changed_[sp.patch] = 1;
        }
    subdivision_.take_spare(std::move(t.trees.nodes), std::move(t.subpatches));
}

} // namespace seamless
