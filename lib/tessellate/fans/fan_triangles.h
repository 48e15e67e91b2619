// SPDX-License-Identifier: MIT
// Steps (d3) and (d4) of a tessellation pass (paper section 6): each planar
// subpatch becomes the fan from its centre over its ring, with the exact
// surface normals and (u, v) at the corners, and the fan hangs below the
// subpatch in its binary patch tree (Proposition 11, remark 2).
#pragma once

#include <seamless/spline/bezier_patch.h>
#include <seamless/tessellate/fans/subpatch_ring.h>
#include <seamless/tessellate/tessellation_options.h>
#include <seamless/tessellate/tessellation_result.h>

#include <vector>

namespace seamless {

// Unit normals at every ring vertex and centre (unit_normal, spline/surface_point.h);
// `leaf_start`: where each patch's subpatches start, one more entry: the end.
struct FanNormals {
    std::vector<Vec3> ring, centre;
};
FanNormals fan_normals(const std::vector<BezierPatch>& patches,
                       const std::vector<Subpatch>& subpatches, const std::vector<int>& leaf_start,
                       const SubpatchRings& rings, int threads);

// The fan triangles in subpatch order into out.mesh, none where two ring
// vertices are one (a pole); Subpatch::first_triangle and triangle_count; the
// triangles as leaves of out.trees and every node's triangle_hull
// (`node_start`: where each patch's nodes start, one more entry: the end;
// null: no trees, TessellationOptions::patch_trees);
// out.mesh.positions = `positions`; stats max_depth and nonplanar_subpatches.
// The hulls come out multiplied by `hull_scale` (a power of two: a pass at
// unit scale gives them in the model's units, exactly, tessellation.cpp).
// Counted per subpatch, placed by prefix sums, written in parallel: the same
// arrays for any thread count.
void write_fans(const std::vector<BezierPatch>& patches, const SubpatchRings& rings,
                const FanNormals& normals, const std::vector<int>* node_start,
                std::vector<Vec3>&& positions, double hull_scale, int threads, Tessellation& out);

} // namespace seamless
