// SPDX-License-Identifier: MIT
// A face's (u,v) domain as a constrained Delaunay triangulation: CGAL's
// Constrained_Delaunay_triangulation_2 with exact predicates, kept behind
// this seamless-typed interface so that CGAL is compiled in one .cpp only.
// The constraints are the face's discretised loops; the domain is what lies
// at odd nesting depth across them (CGAL's polygon-with-holes example), so
// the loops' orientation does not matter. Points are (x, y, 0).
#pragma once

#include <seamless/base/vec.h>

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace seamless {

struct DomainTriangle {
    std::array<int, 3> corners;   // point indices, counter-clockwise
    std::array<bool, 3> boundary; // edge opposite corner k is a constraint
    int tag = -1; // set_tag's value, while the triangle has the same corners; else -1
};

class ConstrainedTriangulation {
  public:
    ConstrainedTriangulation();
    ~ConstrainedTriangulation();
    ConstrainedTriangulation(const ConstrainedTriangulation&) = delete;
    ConstrainedTriangulation& operator=(const ConstrainedTriangulation&) = delete;

    // Points 0..n-1 and the constraint segments between them. Points with the
    // same key are one mesh vertex: coinciding, they merge. False when two
    // points with different keys coincide, two constraints cross or overlap,
    // or a constraint passes through a point (each would split a boundary
    // segment, a crack): the caller re-splits the edges, or moves points and
    // builds again (each build starts from nothing).
    bool build(const std::vector<Vec3>& points, const std::vector<std::int64_t>& keys,
               const std::vector<std::array<int, 2>>& segments);
    // Why build() failed: the pairs of segments (indices into `segments`)
    // that cross, overlap, or where one passes through the other's end point,
    // found with the same exact predicates; two points with different keys
    // at one place count as their segments' conflict.
    struct Conflict {
        int a = 0, b = 0;     // a < b
        bool overlap = false; // collinear along a length: splitting never parts them
    };
    static std::vector<Conflict> conflicts(const std::vector<Vec3>& points,
                                           const std::vector<std::int64_t>& keys,
                                           const std::vector<std::array<int, 2>>& segments);
    // The domain's triangles, in the triangulation's (deterministic) order.
    void triangles(std::vector<DomainTriangle>& out);
    // Tags triangle k of the last triangles() list: a caller's note (a
    // verdict) that comes back with the triangle as long as insertions leave
    // it as it is, without a lookup by its corners.
    void set_tag(int k, int tag);
    // Inserts p as point size() when it lies strictly inside a domain
    // triangle at least `clearance` from its corners and from its boundary
    // edges; returns its index, else kOutside (outside the domain or too near
    // a boundary edge) or kCrowded (too near a corner). The search for p's
    // triangle starts at point `near` (any index: a near one is fast).
    static constexpr int kOutside = -1, kCrowded = -2;
    int insert(Vec3 p, double clearance, int near);
    int size() const { return points_; }

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    int points_ = 0;
};

} // namespace seamless
