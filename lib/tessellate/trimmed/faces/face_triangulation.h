// SPDX-License-Identifier: MIT
// Faces in parameter space (issue 28, section 2): a face's domain
// (face_domain.h) triangulated by a constrained Delaunay triangulation whose
// constraints are exactly its discretised loops, then refined inside, never
// on a constraint, until every triangle is within the deviation of the
// surface at its barycentric samples and its corner normals within the
// angle. Triangles come out oriented outward (BRepFace::reversed applied).
#pragma once

#include <seamless/model/model.h>
#include <seamless/tessellate/trimmed/edge_discretisation.h>
#include <seamless/tessellate/trimmed/faces/face_domain.h>
#include <seamless/tessellate/trimmed/faces/triangle_verdict.h>

#include <array>
#include <cstdint>
#include <vector>

namespace seamless {

struct FaceCriteria {
    double deviation = 0; // D, model units
    double angle = 0.5;   // radians
    std::int64_t max_triangles = 10'000'000;
    // Stop refining once a boundary segment has been found encroached in
    // several rounds (refinement does not mend it): the face is redone after
    // such segments are halved, so refining it further is wasted. All but
    // the last re-split round.
    bool stop_when_encroached = false;
};

struct FaceMesh {
    FaceDomain domain;                         // boundary points, then the interior ones
    std::vector<std::array<int, 3>> triangles; // domain point indices, outward
    std::vector<std::array<Vec3, 3>> normals;  // unit surface normals at the corners, outward
    double deviation = 0;                      // largest sampled deviation of the triangles
    int above_tolerance = 0;                   // triangles the limits left above D or the angle
    long long judged = 0;                      // triangles judged (a work counter)
    bool failed = false; // the loops did not triangulate (crossing or overlapping segments)
    // When triangles stay above the limits: boundary segments (indices into
    // domain.segments) whose triangles' circumcentres fell outside the face
    // (Ruppert's encroachment): no interior point mends such a triangle,
    // halving the segment does.
    std::vector<int> encroached;
    // Stopped by stop_when_encroached after its refinement ran on beside
    // those segments (more triangles per boundary point than converged
    // faces have): its interior points would crowd a redo.
    bool crowded = false;
    // Its triangles within the limits, for a redo from its points.
    AcceptedTriangles accepted;
};

// Throws TriangleBudgetError (file `model.source`) past max_triangles.
// `seeds`, when given, is an earlier mesh of the face, redone after a
// round re-split edges of its own or of a neighbour's (face_seeds.h).
FaceMesh triangulate_face(const Model& model, const std::vector<EdgePolyline>& lines, int face,
                          const FaceCriteria& criteria, const FaceMesh* seeds = nullptr);

} // namespace seamless
