// SPDX-License-Identifier: MIT
// Clusters of secondary rays against triangles (paper section 5, Proposition 11).
// A cluster is {O + q D : O in [O], D in [D], q in [q]}; a ray of it meets the
// triangle T(beta, delta) = T1 + beta (T2 - T1) + delta (T3 - T1) iff
//   0 = b + A w,  w = (beta, delta, q - q~),  b = T1 - (O + q~ D),  A = (T2 - T1, T3 - T1, -D),
// with beta, delta >= 0, beta + delta <= 1 and q in [q]. The interval system is
// contracted by the Hansen-Sengupta operator (Theorem 6): an empty result
// proves that no ray of the cluster meets the triangle.
#pragma once

#include <seamless/base/vec.h>
#include <seamless/interval/interval_matrix.h>

#include <array>
#include <vector>

namespace seamless {

struct RayCluster {
    IVec<3> origin, direction;
    Interval q{0.0, 1.0};
};

// Axis-aligned box holding every point of every ray of the cluster.
Box3 cluster_box(const RayCluster& c);

// Hull comparison of a cluster with the boxes of the patch trees (Proposition 11,
// remarks 1-2). Besides the axis-aligned hull of the cluster, the cluster and a
// box are compared along two axes across the cluster's mean direction, which
// rejects most boxes that a long, thin, diagonal cluster's axis-aligned hull
// would accept. Conservative: false only when no ray can meet the box.
class ClusterHull {
  public:
    explicit ClusterHull(const RayCluster& c);
    bool may_meet(const Box3& b) const;

  private:
    Box3 box_;
    Vec3 axis_[2];
    Interval proj_[2];
};

// true: every ray of the cluster certainly meets the triangle's interior, once,
// at a ray parameter inside `q` (Theorem 6 iii on the system of Proposition 11);
// q receives the enclosure of those parameters, beta and delta (optional) the
// enclosures of the meeting points' triangle parameters.
bool covers_triangle(const RayCluster& c, Vec3 T1, Vec3 T2, Vec3 T3, Interval& q,
                     Interval* beta = nullptr, Interval* delta = nullptr);

// false when covers_triangle certainly answers false: the cluster's middle ray
// (midpoint origin, midpoint direction: both in the cluster's boxes) certainly
// misses the closed triangle (Cramer's rule on Proposition 11's system in
// interval arithmetic), and a triangle that every ray meets is met by that one.
// A few interval products, against covers_triangle's Hansen-Sengupta steps.
bool may_cover_triangle(const RayCluster& c, Vec3 T1, Vec3 T2, Vec3 T3);

// false: certainly no ray of the cluster meets the triangle (Proposition 11);
// true: some ray may meet it.
bool may_hit_triangle(const RayCluster& c, Vec3 T1, Vec3 T2, Vec3 T3);

// Both questions on one triangle with one interval system (built once):
// miss when may_hit_triangle is false, covers when it is true and
// covers_triangle is true too (q, beta, delta set as there), may otherwise.
enum class TriangleMeeting { miss, may, covers };
TriangleMeeting meet_triangle(const RayCluster& c, Vec3 T1, Vec3 T2, Vec3 T3, Interval& q,
                              Interval* beta = nullptr, Interval* delta = nullptr);

// A cluster from one point (a light) to a box of end points, q in [0, 1]:
// its rays' points are the convex hull of the apex and the box. false when a
// plane certainly separates that hull from the triangle: the triangle's own
// plane (apex and box strictly on one side), or a side plane of the pyramid
// from the apex over the triangle (the box strictly outside it, the apex off
// the triangle's plane). Exact
// predicates evaluated in interval arithmetic; tighter than
// may_hit_triangle for these clusters, whose direction box is wide.
bool pyramid_may_meet_triangle(Vec3 apex, const IVec<3>& ends, Vec3 T1, Vec3 T2, Vec3 T3);

// The part of pyramid_may_meet_triangle that depends on the apex and the
// triangle only, not on the box: the triangle's plane, the apex's side of it
// and the three side planes through the apex. A light's shadow pyramids all
// share it, so INTRACY forms it once per light and triangle (trace.h).
struct ApexTriangle {
    Vec3 apex, T1;
    std::array<Interval, 3> normal; // (T2 - T1) x (T3 - T1)
    Interval apex_side;             // normal . (apex - T1)
    std::array<Interval, 3>
        side[3];       // edge e: (P - apex) x (Q - apex), P Q R = edge e's corners, then the third
    Interval inner[3]; // side[e] . (R - apex)
};
ApexTriangle apex_triangle(Vec3 apex, Vec3 T1, Vec3 T2, Vec3 T3);
// pyramid_may_meet_triangle(apex, ends, T1, T2, T3) for p = apex_triangle(apex,
// T1, T2, T3): the same interval operations, so the same answer.
bool pyramid_may_meet_triangle(const ApexTriangle& p, const IVec<3>& ends);

} // namespace seamless
