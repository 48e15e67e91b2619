// SPDX-License-Identifier: MIT
// Exact points of a B-rep's faces and edges for the deviation measures
// (brep_deviation.h): on each face a grid of (u,v) cell centres over its
// loops' box kept where the face is (face_region.h), and points along each
// edge's 3D curve, both spaced by their 3D extent.
#pragma once

#include <seamless/mesh/deviation/face_region.h>
#include <seamless/model/model.h>

#include <vector>

namespace seamless {

struct BRepSamplingOptions {
    // Per face: cells of a grid over its (u,v) box about `spacing` apart in
    // 3D, at least min_grid in each direction and at most max_grid^2 in all.
    int min_grid = 16, max_grid = 400;
    double spacing = 0; // model units; 0: min_grid
    // Per edge: between min_edge_samples and max_edge_samples points, `spacing` apart.
    int min_edge_samples = 16, max_edge_samples = 4096;
};

struct FaceSample {
    Vec3 point;
    int face = 0;
    double u = 0, v = 0; // on the face's surface, wrapped into its domain
};

struct EdgeSample {
    Vec3 point;
    int edge = 0;
    double t = 0;
};

std::vector<FaceSample> face_samples(const Model& model, int face, const FaceRegion& region,
                                     const BRepSamplingOptions& options);
// Nothing for a degenerate edge (its points are the vertex).
std::vector<EdgeSample> edge_samples(const Model& model, int edge,
                                     const BRepSamplingOptions& options);

// Diagonal of the box of the B-rep's vertices and edge curves' control
// points: the part's size, which the surfaces' control nets (a plane's may
// extend far beyond its faces) can overstate.
double brep_diagonal(const Model& model);

} // namespace seamless
