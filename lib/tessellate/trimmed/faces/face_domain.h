// SPDX-License-Identifier: MIT
// A face's boundary in its (u,v) domain: the loops' shared edge polylines
// mapped through the pcurves at the edges' parameters (a reversed coedge
// runs them backwards), each point keyed by the mesh vertex it is (a B-rep
// vertex or an edge's point), so that both sides of a seam and every point of
// a pole's degenerate edge are one vertex. The domain is rescaled by the
// surface's mean metric and curvature so that Delaunay triangles in it are
// about as long on the surface as the deviation allows each way.
#pragma once

#include <seamless/model/model.h>
#include <seamless/tessellate/trimmed/edge_discretisation.h>
#include <seamless/tessellate/trimmed/face_surface.h>

#include <array>
#include <cstdint>
#include <vector>

namespace seamless {

// The mesh vertex of point k of edge e's polyline: its B-rep vertex (the
// key is the vertex index) at the ends and on a degenerate edge, else a key
// above every vertex index.
std::int64_t boundary_key(const BRep& brep, int edge, int k, const EdgePolyline& line);
inline bool is_vertex_key(std::int64_t key) {
    return key >= 0 && key < (std::int64_t(1) << 32);
}
inline std::int64_t edge_point_key(int edge, int k) {
    return (std::int64_t(edge) + 1) << 32 | k;
}

struct FaceDomain {
    // Per point: (u, v, 0), the rescaled (su u, sv v, 0), the 3D point, the
    // key of its mesh vertex (boundary_key; -1 inside the face), and at a pole
    // the unit (u,v) direction of its degenerate edge (else zero).
    std::vector<Vec3> uv, scaled, points;
    std::vector<std::int64_t> keys;
    std::vector<Vec3> pole;
    // Per point: how far it lies off the surface, |point - S(uv)|: a boundary
    // point lies on its edge's curve, which the file's pcurve maps up to the
    // edge's tolerance away; an interior point lies on the surface (zero).
    std::vector<double> offset;
    std::vector<std::array<int, 2>> segments; // the loops' segments, point indices
    // Per segment: its edge, its segment of the edge's polyline (k: from
    // point k to k + 1), which re-splitting halves, and the coedge's pcurve.
    struct Origin {
        int edge = 0, segment = 0, pcurve = 0;
    };
    std::vector<Origin> origins;
    double su = 1, sv = 1; // the scale of u and v (metric and curvature)
    double tolerance = 0;  // largest tolerance of the face's edges
    int boundary_points = 0;

    int size() const { return static_cast<int>(uv.size()); }
    // Appends an interior point at rescaled (x, y); returns its index.
    int add_interior(const FaceSurface& s, Vec3 at_scaled);
    // ... whose (u,v) point is `uv` itself (an earlier run's point, which
    // its rescaling back would move by a rounding).
    int add_interior(const FaceSurface& s, Vec3 at_scaled, Vec3 uv);
    // The offsets of the points `corners` interpolated at barycentric l: how
    // far the flat triangle's point may lie off the surface by them.
    double offset_at(const std::array<int, 3>& corners, const double l[3]) const {
        return l[0] * offset[corners[0]] + l[1] * offset[corners[1]] + l[2] * offset[corners[2]];
    }
    // Rescaled point `at` lies across the side between points a and b from
    // point c, or within the side's diametral circle (Ruppert's encroachment).
    bool encroaches(Vec3 at, int a, int b, int c) const;
    // The segments (indices into `segments`) joining the given pairs of
    // points, sorted, each once.
    std::vector<int> segments_joining(std::vector<std::array<int, 2>> sides) const;
};

FaceDomain face_domain(const Model& model, const std::vector<EdgePolyline>& lines, int face);

// Centre of the box of the face's pcurves' control points: a (u,v) point
// towards the inside of a face from its poles (EdgeOnFace::inward).
Vec3 face_uv_centre(const BRep& brep, const BRepFace& face);

} // namespace seamless
