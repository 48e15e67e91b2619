// SPDX-License-Identifier: MIT
#include <seamless/base/error.h>
#include <seamless/base/parallel/parallel.h>
#include <seamless/base/phase_clock.h>
#include <seamless/tessellate/bounds/fan_certification.h>
#include <seamless/tessellate/fans/fan_triangles.h>
#include <seamless/tessellate/fans/subpatch_ring.h>
#include <seamless/tessellate/fans/vertex_numbering.h>
#include <seamless/tessellate/pass_progress.h>
#include <seamless/tessellate/seams/edge_graph.h>
#include <seamless/tessellate/seams/shared_edges.h>
#include <seamless/tessellate/seams/surface_orientation.h>
#include <seamless/tessellate/subdivision/patch_subdivision.h>
#include <seamless/tessellate/tessellation_pass.h>

#include <algorithm>
#include <chrono>
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

// What only the numbering and another pass need: the previous pass's
// registry, rings and positions (copied from by now), this pass's registry and
// the rings' keys, and the memo's per-patch tables and trees (freed patch by
// patch in parallel rather than on the calling thread). Freed before the mesh
// is built, whose normals, fans and orientation refill their pages. Teapot
// 1e-4 d_max, 2 passes, 1 thread: those phases' page faults 3,173 -> 131
// (getrusage per phase), i11r.
void release_before_mesh(PassMemo& memo, EdgeRegistry& reg, SubpatchRings& rings, int threads) {
    memo.registry = EdgeRegistry();
    memo.rings = SubpatchRings();
    std::vector<Vec3>().swap(memo.positions);
    memo.rings_kept = false;
    reg = EdgeRegistry();
    std::vector<VertexKey>().swap(rings.keys);
    const int np = static_cast<int>(memo.parts.size());
    parallel_chunks(np, threads, [&](int begin, int end) {
        for (int p = begin; p < end; ++p) {
            memo.verdicts[p] = FanMemo();
            memo.bounds[p] = KnownBounds();
            memo.parts[p] = Part();
        }
    });
}

} // namespace

void refuse_triangle_budget(const Model& model, const TessellationOptions& options) {
    throw TriangleBudgetError(model.source, options.tolerance > 0 ? "tolerance" : "eps1, eps2",
                              options.max_triangles);
}

Tessellation tessellate_pass(const Model& model, const std::vector<BezierPatch>& patches,
                             const TessellationOptions& options,
                             const std::unordered_set<std::uint64_t>& split, PassMemo& memo,
                             bool last, double hull_scale, int pass) {
    const PassProgress progress(options.progress, pass);
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
    const PatchRanges ranges = subdivide_patches(
        patches, sub, D, options.threads, memo, options.patch_trees ? &out.trees : nullptr,
        out.subpatches, std::max<std::int64_t>(options.max_triangles, 0) / 4, &progress);
    if (ranges.over_budget) refuse_triangle_budget(model, options);
    phase.subdivision += lap();
    progress.at(PassProgress::kSubdivided);

    // (b) Shared boundaries, poles and welded corners; (c) the subpatch sides on every line.
    // Shared boundaries agree to the seam tolerance, and at least to the
    // rounding of knot insertion, which scales with the coordinates'
    // magnitude, not with d_max: a model far from the origin needs the larger.
    st.seam_tolerance =
        std::max(options.seam_tolerance >= 0 ? options.seam_tolerance : 1e-9 * st.d_max,
                 64 * std::numeric_limits<double>::epsilon() * scale);
    if (memo.match_tolerance != st.seam_tolerance) {
        memo.match = match_boundaries(patches, st.seam_tolerance);
        memo.match_tolerance = st.seam_tolerance;
    }
    const BoundaryMatch& match = memo.match;
    st.shared_edges = match.shared_edges;
    st.collapsed_edges = match.collapsed_edges;
    // A patch not split again keeps its sides and interior lines (the
    // previous pass's registry, PassMemo).
    const int np = static_cast<int>(patches.size());
    std::vector<char> kept(np, 0);
    PreviousRegistry previous_registry;
    if (!memo.leaf_start.empty()) {
        for (int p = 0; p < np; ++p) kept[p] = !memo.changed[p];
        previous_registry = {&memo.registry, &memo.leaf_start, &kept};
    }
    EdgeRegistry reg =
        build_edge_registry(match, out.subpatches, options.threads, previous_registry);
    // The previous pass's registry is copied from by now: freed, so that the
    // rings and the numbering refill its pages.
    memo.registry = EdgeRegistry();
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
    progress.at(PassProgress::kBoundaries);

    // (d) Fans: each planar subpatch from its centre over its ring.
    TriangleMesh& mesh = out.mesh;
    for (const BSplineSurface& s : model.surfaces) mesh.surface_names.push_back(s.name);
    // (d0) Each subpatch's ring and centre point on its own, in parallel.
    // A patch's rings are the previous pass's when neither it nor a patch
    // across its edges was split again (its sides' lines hold the same
    // segments), and no seam vertices or aliases are involved; so are their
    // vertices' positions (each the exact point of its key).
    std::vector<char> same(np, 0);
    PreviousRings previous;
    if (memo.rings_kept && graph.points.empty() && graph.alias.empty()) {
        same = unchanged_rings(match, memo.changed);
        previous = {&memo.rings, &memo.leaf_start, &ranges.leaf_start, &same, &memo.positions};
    }
    SubpatchRings rings = collect_rings(patches, out.subpatches, reg, graph, options.crack_free,
                                        options.threads, previous);
    phase.rings += lap();
    progress.at(PassProgress::kRings);
    // (d1) Their vertices, numbered as first met in subpatch order (each ring,
    // then its centre).
    number_vertices(out.subpatches, ranges.leaf_start, graph, options.threads, vr, rings, previous);
    phase.numbering += lap();
    progress.at(PassProgress::kNumbered);

    // (d2) Each subpatch's certified bound on its own, in parallel.
    const bool certify = options.certify || st.tolerance > 0;
    if (certify) {
        const std::vector<char> fresh =
            certify_fans(patches, rings, vr.positions, scale, st.tolerance, options.threads,
                         previous.same, memo.bounds, out.subpatches, &progress);
        std::vector<char> next_changed(np, 0);
        for (const Subpatch& sp : out.subpatches) {
            if (st.tolerance > 0 && sp.error_bound > st.tolerance) ++st.above_tolerance;
            st.max_error_bound = std::max(st.max_error_bound, sp.error_bound);
            next_changed[sp.patch] |= splits_again(sp, st.tolerance, options.max_depth);
        }
        // For the next pass, if one follows: the rings of patches it may
        // compare rings of (all where this pass's rings are not kept).
        if (memo.keep && !last && st.above_tolerance > 0) {
            const bool kept = graph.points.empty() && graph.alias.empty();
            std::vector<char> compared;
            if (kept) {
                compared = unchanged_rings(match, next_changed);
                for (char& c : compared) c = !c;
            }
            keep_fan_bounds(rings, vr.positions, ranges.leaf_start, options.threads, fresh,
                            kept ? &compared : nullptr, out.subpatches, memo.bounds);
        }
    } else {
        for (Subpatch& sp : out.subpatches)
            sp.error_bound = std::numeric_limits<double>::quiet_NaN();
        st.max_error_bound = std::numeric_limits<double>::quiet_NaN();
    }
    phase.bounds += lap();
    progress.at(PassProgress::kBounded);
    // Another pass will follow: the mesh of this one is not needed.
    if (!last && st.above_tolerance > 0) {
        if (memo.keep) {
            memo.leaf_start = ranges.leaf_start;
            memo.registry = std::move(reg);
            memo.rings_kept = graph.points.empty() && graph.alias.empty();
            if (memo.rings_kept) {
                memo.rings = std::move(rings);
                memo.positions = std::move(vr.positions);
            }
        }
        return out;
    }
    // The mesh follows: what only the numbering and another pass needed goes
    // first, so that the normals, fans and orientation refill its pages
    // instead of faulting in fresh ones.
    release_before_mesh(memo, reg, rings, options.threads);

    // (d3) Normals at the fans' vertices, in parallel.
    const FanNormals normals =
        fan_normals(patches, out.subpatches, ranges.leaf_start, rings, options.threads);
    phase.normals += lap();
    progress.at(PassProgress::kNormals);

    // (d4) Fan triangles in subpatch order, their patch-tree leaves and hulls.
    write_fans(patches, rings, normals, options.patch_trees ? &ranges.node_start : nullptr,
               std::move(vr.positions), hull_scale, options.threads, out);
    phase.fans += lap();
    progress.at(PassProgress::kFans);

    // At unit scale: the signed volume of a closed component stays finite.
    if (options.orient_surfaces)
        st.flipped_surfaces = orient_surfaces(mesh, options.threads).flipped_surfaces;
    phase.orientation += lap();
    progress.at(1.0);

    st.subpatches = static_cast<int>(out.subpatches.size());
    st.triangles = mesh.triangle_count();
    st.vertices = mesh.vertex_count();
    st.seconds = seconds_since(start);
    return out;
}

} // namespace seamless
