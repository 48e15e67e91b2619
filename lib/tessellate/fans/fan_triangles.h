// SPDX-License-Identifier: MIT
// Steps (d3) and (d4) of a tessellation pass (paper section 6): each planar
// subpatch becomes the fan from its centre over its ring (or, with a
// tolerance, two triangles over its four corners where they are certified
// within it), with the exact surface normals and (u, v) at the corners, and
// the triangles hang below the subpatch in its binary patch tree
// (Proposition 11, remark 2).
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

// What write_fans makes the fans of: the patches, every subpatch's ring
// (numbered, vertex_numbering.h) and the normals at its vertices;
// `node_start`: where each patch's nodes start, one more entry: the end (null:
// no trees, TessellationOptions::patch_trees). The hulls come out multiplied
// by `hull_scale` (a power of two: a pass at unit scale gives them in the
// model's units, exactly, tessellation.cpp).
struct FanSources {
    const std::vector<BezierPatch>* patches = nullptr;
    const SubpatchRings* rings = nullptr;
    const FanNormals* normals = nullptr;
    const std::vector<int>* node_start = nullptr;
    double hull_scale = 1;
    int threads = 1;
};

// The fan triangles in subpatch order into out.mesh, none where two ring
// vertices are one (a pole), or a subpatch's two triangles
// (Subpatch::diagonal); Subpatch::first_triangle and triangle_count; the
// triangles as leaves of out.trees and every node's triangle_hull;
// out.mesh.positions = `positions` without the centres of two-triangle
// subpatches; stats max_depth, nonplanar_subpatches and
// two_triangle_subpatches.
// Counted per subpatch, placed by prefix sums, written in parallel: the same
// arrays for any thread count.
void write_fans(const FanSources& in, std::vector<Vec3>&& positions, Tessellation& out);

} // namespace seamless
