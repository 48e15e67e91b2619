// SPDX-License-Identifier: MIT
// Measured two-way deviation between a model's exact surfaces and its
// tessellation (paper section 8: accuracy against run time), to set beside the
// a-priori bound Subpatch::error_bound (tessellate/bounds/error_bound.h).
//   surface -> mesh: exact points S(s,t) on a grid of every Bezier patch and of
//     every planar subpatch, to the closest point of the mesh (CGAL AABB tree);
//   mesh -> surface: barycentric samples of every triangle, projected onto the
//     triangle's B-spline surface by Newton's method from the parameter the
//     corner_uvs interpolate (a local minimum distance), and the plain
//     same-parameter distance |S(uv(x)) - x| (an upper estimate of the
//     distance to the surface, with the parametrisation's tangential drift:
//     reported beside, not bounded).
// The first two are lower estimates of the Hausdorff distance (finite samples)
// and must stay below the certified bound max_error_bound (tessellate/bounds/error_bound.h).
#pragma once

#include <seamless/model/model.h>
#include <seamless/tessellate/tessellation.h>

#include <vector>

namespace seamless {

struct DeviationOptions {
    // Surface -> mesh: patch_grid x patch_grid points (boundary included) per
    // Bezier patch and subpatch_grid x subpatch_grid points at the cell centres
    // ((i + 1/2) / subpatch_grid) of every planar subpatch.
    int patch_grid = 33;
    int subpatch_grid = 2;
    // Mesh -> surface: barycentric points (i, j, k) / triangle_level with
    // i + j + k = triangle_level per triangle (2: corners and edge midpoints),
    // plus the centroid.
    int triangle_level = 2;
    int newton_iterations = 12;
    // 0: std::thread::hardware_concurrency(). The result does not depend on it.
    int threads = 0;
};

struct DeviationStats {
    double max = 0, rms = 0; // model units
    long long samples = 0;
    Vec3 at; // where the largest distance was sampled (on the side measured from)
};

struct Deviation {
    DeviationStats surface_to_mesh;     // exact surface points to the closest mesh point
    DeviationStats mesh_to_surface;     // mesh points to their Newton projection
    DeviationStats mesh_same_parameter; // mesh points to S at their interpolated (u,v)
    double seconds = 0;
    // The measured two-way distance, max(surface_to_mesh, mesh_to_surface);
    // <= the tessellation's max_error_bound.
    double max() const;
};

// `t` must be tessellate(model, ...) of this model (its subpatches and the
// mesh's corner_uvs are used).
Deviation measure_deviation(const Model& model, const Tessellation& t,
                            const DeviationOptions& options = {});
// Any mesh of the model's surfaces (another tessellator's, for comparison):
// triangle_surface and corner_uvs (the source surface's (u,v)) give each
// triangle's surface; without them only surface -> mesh is measured.
Deviation measure_deviation(const Model& model, const TriangleMesh& mesh,
                            const DeviationOptions& options = {});

} // namespace seamless
