// SPDX-License-Identifier: MIT
// Crack-free adaptive tessellation of a model (paper section 6): every Bezier
// patch is split by the planarity test, or until a requested deviation is
// certified (subdivision.h, error_bound.h), shared boundaries are matched
// across patches and surfaces (shared_edges.h, edge_graph.h), vertices follow the
// straight-midpoint rule of Fig. 3 (with a requested tolerance: exact surface
// points, VertexRegistry::straight_segments), each planar subpatch becomes a fan from
// its centre over every vertex on its sides, and the binary patch trees of
// Proposition 11, remark 2 are built in the same pass.
#pragma once

#include <seamless/base/error.h>
#include <seamless/model/model.h>
#include <seamless/tessellate/patch_tree.h>
#include <seamless/tessellate/subdivision.h>
#include <seamless/tessellate/triangle_mesh.h>

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace seamless {

// The paper's planarity tolerances (section 8), scaled by `factor`:
// eps1 = factor * 0.001 * d_max, eps2 = factor * 0.02 * d_max, d_max the
// largest extent of the bounding box of the model's control points.
struct PlanarityTolerances {
    double eps1 = 0, eps2 = 0;
};
inline PlanarityTolerances paper_tolerances(double d_max, double factor = 1) {
    return {factor * 0.001 * d_max, factor * 0.02 * d_max};
}

struct TessellationOptions {
    // Planarity tolerances in model units; < 0 selects paper_tolerances(d_max)
    // when no tolerance is given, and no planarity test when one is.
    double eps1 = -1, eps2 = -1;
    // > 0: the requested deviation, model units: subdivide until every
    // subpatch's certified two-way distance to its triangles (error_bound.h) is
    // at most this.
    double tolerance = 0;
    // > 0: split until every fan triangle's normal is within angle / 2 of the
    // exact normals at its corners, so neighbouring triangles differ by at most
    // `angle` (radians).
    double angle = 0;
    // Safeguard against subpatches that never become planar: at most this many
    // halvings below a Bezier patch (such subpatches are counted in the stats).
    int max_depth = 24;
    // Budget: a tolerance (or eps1, eps2) that needs more triangles than this
    // is refused with an InputError instead of filling the memory (peak memory
    // is about 0.7 KB per triangle: teapot at 6.5e-5, 1.14 M triangles, 779
    // MB). Counted during the subdivision as four triangles per subpatch (a
    // fan has at least four), and checked again on the final mesh.
    std::int64_t max_triangles = 10'000'000;
    // Called with the fraction done (0..1), from any thread, a few hundred
    // times at most per pass (pass_progress.h); empty: nothing is reported.
    std::function<void(double)> progress;
    // false: the naive rule (every vertex the exact surface point, four
    // triangles per subpatch whatever the neighbours did), which leaves cracks;
    // kept so tests can show the difference.
    bool crack_free = true;
    // Seam tolerance in model units: boundaries of patches and surfaces closer
    // than this are one edge (edge_graph.h); < 0 selects 1e-9 * d_max (and at
    // least the rounding of knot insertion at the coordinates' magnitude). CAD
    // data whose surfaces meet only within the exporter's tolerance needs that
    // tolerance here, typically 1e-7 to 1e-3 model units.
    double seam_tolerance = -1;
    // Flip whole surfaces so that every shared edge runs in opposite directions
    // on its two sides and closed components face outward
    // (surface_orientation.h); false keeps each surface's dP/du x dP/dv side.
    bool orient_surfaces = true;
    // Worker threads (0: every core, 1: sequential). The output, vertex order
    // included, is the same for any count.
    int threads = 0;
    // false: leave out the certified bound of every subpatch (error_bound.h;
    // about half the time in planarity mode) when no tolerance is given;
    // Subpatch::error_bound and TessellationStats::max_error_bound are then NaN.
    // For callers that only need the triangles (TRAY, topology tests). A
    // tolerance needs the bound and computes it whatever this says.
    bool certify = true;
    // false: no patch trees (Tessellation::trees stays empty, Subpatch::node
    // unused); the mesh, subpatches and stats are the same. The trees are the
    // renderer's (TRAY); a caller that only writes the mesh skips about 150,000
    // nodes of 120 bytes (teapot at D = 0.001: 18 MB of fresh memory, about
    // 4,500 page faults at ~11 us each on the AMD EPYC VM, i11o).
    bool patch_trees = true;
};

// Wall-clock seconds of the phases of tessellate(), summed over the passes
// (docs/formats.md, `phase_seconds`). In parallel: subdivision, rings,
// bounds, normals, scaling (the power-of-two scale in and out), and but for
// prefix sums fans (triangles, patch-tree leaves, hulls), orientation and,
// without straight segments, numbering (vertices in subpatch order); on one
// thread: boundaries (shared edges, edge registry and graph).
struct PhaseSeconds {
    double subdivision = 0, boundaries = 0, rings = 0, numbering = 0, bounds = 0, normals = 0,
           fans = 0, orientation = 0, scaling = 0;
};

struct TessellationStats {
    int surfaces = 0, patches = 0, subpatches = 0, triangles = 0, vertices = 0;
    int shared_edges = 0, collapsed_edges = 0;
    int seams = 0, seam_vertices = 0;     // boundaries matched geometrically (edge_graph.h)
    int flipped_surfaces = 0;             // turned by orient_surfaces
    int nonplanar_subpatches = 0;         // stopped by max_depth
    int max_depth = 0;                    // deepest subpatch
    double d_max = 0, eps1 = 0, eps2 = 0; // eps: 0 when the planarity test was off
    double seam_tolerance = 0;
    double tolerance = 0; // requested (0: none), model units
    // Largest Subpatch::error_bound: the certified two-way distance between the
    // surfaces and the mesh, model units (NaN when TessellationOptions::certify
    // left it out).
    double max_error_bound = 0;
    // Subpatches whose final bound exceeds the tolerance (neighbours moved a
    // corner onto their straight edge after the subpatch passed), or that
    // max_depth stopped.
    int above_tolerance = 0;
    int passes = 1; // tessellation passes (a tolerance may need more than one)
    double seconds = 0;
    PhaseSeconds phases;
};

// What tessellate() throws past TessellationOptions::max_triangles: an
// InputError naming the model and the tolerance that asked for it, with the
// limit kept so a front end can name its own way to raise it.
class TriangleBudgetError : public InputError {
  public:
    TriangleBudgetError(std::string file, std::string field, std::int64_t limit)
        : InputError(std::move(file), std::move(field), message_for(limit, "max_triangles")),
          limit_(limit) {}
    std::int64_t limit() const { return limit_; }
    // The message, with the limit called by `name` (a front end's own flag).
    static std::string message_for(std::int64_t limit, const std::string& name) {
        return "needs more than " + std::to_string(limit) + " triangles, the " + name +
               " limit; a larger tolerance needs fewer";
    }

  private:
    std::int64_t limit_;
};

struct Tessellation {
    TriangleMesh mesh;
    PatchTrees trees;
    // Planar subpatches in tree order, with their triangle ranges and error bounds.
    std::vector<Subpatch> subpatches;
    TessellationStats stats;
};

Tessellation tessellate(const Model& model, const TessellationOptions& options = {});

// Same, from Bezier patches already extracted (bezier_patches(model)); the
// patch indices of the result refer to `patches`.
Tessellation tessellate(const Model& model, const std::vector<BezierPatch>& patches,
                        const TessellationOptions& options);

// Unit normal dP/du x dP/dv at local (s, t) of `b`; where it vanishes (a pole,
// a collapsed edge) the limit normal, approached from (toward_s, toward_t).
Vec3 unit_normal(const BezierPatch& b, double s, double t, double toward_s, double toward_t);
// Where the normal does not vanish at (s, t) itself: true, and in n the same
// value as unit_normal's (then a function of b, s and t alone); else false.
bool regular_unit_normal(const BezierPatch& b, double s, double t, Vec3& n);

} // namespace seamless
