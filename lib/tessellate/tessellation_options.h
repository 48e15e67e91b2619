// SPDX-License-Identifier: MIT
// What a tessellation is asked for (TessellationOptions, one home per
// default): the paper's planarity tolerances (section 6), or a requested
// deviation, certified (Proposition 11's geometric bound, error_bound.h).
#pragma once

#include <cstdint>
#include <functional>

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
    // fan has at least four; two with a tolerance, where a subpatch may be
    // two triangles: Subpatch::diagonal), and checked again on the final mesh.
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
    // renderer's (TRAY); a caller that only writes the mesh skips their fresh
    // memory (about 120 bytes per node, more nodes than triangles) and its
    // page faults.
    bool patch_trees = true;
    // B-rep models (tessellate/trimmed/): false: a face whose loops cannot be
    // triangulated after the edge re-splitting rounds fails the model with an
    // InputError naming it; true: it is left out, a warning names it
    // (BRepStats::warnings), and the mesh has a hole there.
    bool allow_holes = false;
};

} // namespace seamless
