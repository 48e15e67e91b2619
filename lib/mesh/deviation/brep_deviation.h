// SPDX-License-Identifier: MIT
// Measured two-way deviation between a B-rep's trimmed faces (Model::brep)
// and any mesh of them: seamless's or another tessellator's (OpenCASCADE's,
// bench/cad), with the same code, from positions and triangles alone (no
// per-triangle surface or (u,v) assumed).
//   face -> mesh: exact points of every face (brep_samples.h: a grid over its
//     (u,v) box kept inside its loops, and points on its edges' curves), each
//     to the closest point of the mesh (CGAL AABB tree);
//   mesh -> face: barycentric points of every triangle (corners, each vertex
//     once, edge midpoints, centroid) to the closest point of the faces: the nearest
//     face samples seed Newton projection onto their faces' surfaces, kept
//     where the projection lies inside the face's loops; the nearest edge
//     samples seed projection onto the edges' curves (a point whose foot on
//     the surface is outside the face is nearest its boundary) and onto the
//     faces using each edge, from the sample's (u,v) on each (a point beside
//     an edge whose nearest face samples all lie on the other face); the
//     samples themselves count too. The points that may hold the maximum
//     (at or above half of it) are then searched wide: every face and edge
//     with a sample within the distance found plus one sample spacing (a
//     face's closest point has a sample of the face or its boundary about
//     a spacing away), so that the maximum does not depend on which samples
//     happened to be nearest.
// Both maxima are sampled, lower estimates of the Hausdorff distance: a
// point between face samples, or of a triangle between its sample points,
// may lie farther. Each sample's distance is to a point found on the other
// side, so it is at least the true distance of that sample: where Newton
// misses the closest point, mesh -> face overstates it. DeviationStats::at
// says where each maximum was sampled.
#pragma once

#include <seamless/base/triangle_mesh.h>
#include <seamless/mesh/deviation/brep_samples.h>
#include <seamless/mesh/deviation/deviation.h>
#include <seamless/model/model.h>

namespace seamless {

struct BRepDeviationOptions {
    // Face and edge samples about spacing * the B-rep's diagonal (brep_diagonal)
    // apart, within the counts of BRepSamplingOptions (its spacing is set from this).
    double relative_spacing = 2e-3;
    BRepSamplingOptions sampling;
    // Loops' pcurves sampled at least this finely for the inside test, and
    // a quarter of the sample spacing apart along the edge.
    int pcurve_samples = 64;
    // Mesh -> face: barycentric points (i, j, k) / triangle_level, plus the
    // centroid; the corners (the mesh's vertices) once each.
    int triangle_level = 2;
    // Newton projection from each of the newton_seeds nearest face samples
    // (on a folded surface they may lie on different sheets) and from the
    // nearest sample of each of up to max_faces_tried faces among the
    // face_neighbours nearest.
    int face_neighbours = 8;
    int newton_seeds = 4;
    int max_faces_tried = 3;
    // Nearest edge samples, each seeding a projection onto its curve (several:
    // the samples of the edges meeting at a vertex coincide there).
    int edge_neighbours = 4;
    int newton_iterations = 12;
    // The wide search of the points that may hold the maximum (above; a
    // thin cylinder's point whose nearest samples all lie on its denser
    // neighbour's): false, the nearest samples only (off by up to a spacing).
    bool wide_search = true;
    // 0: every core. The result does not depend on it.
    int threads = 0;
};

// `model.brep` must not be empty. Returns surface_to_mesh (face -> mesh) and
// mesh_to_surface (mesh -> face); mesh_same_parameter stays empty.
Deviation measure_brep_deviation(const Model& model, const TriangleMesh& mesh,
                                 const BRepDeviationOptions& options = {});

} // namespace seamless
