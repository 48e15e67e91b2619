// SPDX-License-Identifier: MIT
#include <seamless/render/tray/ray_cluster.h>

#include <seamless/render/tray/interval3.h>

#include <algorithm>
#include <array>
#include <cstdint>

#include <seamless/interval/gauss_seidel.h>
#include <seamless/interval/hansen_sengupta.h>

namespace seamless {

Box3 cluster_box(const RayCluster& c) {
    Box3 b;
    for (double q : {c.q.lo(), c.q.hi()}) {
        Vec3 lo, hi;
        for (int i = 0; i < 3; ++i) {
            const Interval p = c.origin[i] + Interval(q) * c.direction[i];
            lo[i] = p.lo();
            hi[i] = p.hi();
        }
        b.extend(lo);
        b.extend(hi);
    }
    return b;
}

namespace {
// Projection of the cluster's points onto axis a (linear in q: extremes at its ends).
Interval project_cluster(const RayCluster& c, Vec3 a) {
    Interval r = Interval::empty();
    for (double q : {c.q.lo(), c.q.hi()}) {
        Interval d(0.0);
        for (int i = 0; i < 3; ++i)
            d += Interval(a[i]) * (c.origin[i] + Interval(q) * c.direction[i]);
        r = hull(r, d);
    }
    return r;
}
// The interval system 0 = b + A w of Proposition 11 with w = (beta, delta,
// q - q~), q~ the midpoint of the cluster's q, and its preconditioned form for
// the Hansen-Sengupta operator on the linear F(w) = b + A w (Definition 5: A is
// its own Lipschitz matrix, so C = mid(A)^-1 and C A are formed once).
struct TriangleSystem {
    IMat<3> A, CA;
    RMat<3> C;
    IVec<3> b;
    double qt;
    bool preconditioned;

    TriangleSystem(const RayCluster& c, Vec3 T1, Vec3 T2, Vec3 T3) : qt(c.q.mid()) {
        for (int i = 0; i < 3; ++i) {
            A(i, 0) = Interval(T2[i]) - Interval(T1[i]);
            A(i, 1) = Interval(T3[i]) - Interval(T1[i]);
            A(i, 2) = -c.direction[i];
            b[i] = Interval(T1[i]) - (c.origin[i] + Interval(qt) * c.direction[i]);
        }
        // Any real C keeps Theorem 6, so a singular mid(A) falls back to C = I.
        preconditioned = invert<3>(mid(A), C);
        if (!preconditioned) C = identity_matrix<3>();
        CA = C * A;
    }
    // H(x, mid x) before its intersection with x; empty if no zero in x.
    IVec<3> step(const IVec<3>& x) const {
        const IVec<3> xw = to_ivec<3>(mid(x));
        const IVec<3> g = gauss_seidel(CA, -(C * (b + A * xw)), x - xw);
        return g.is_empty() ? IVec<3>::empty() : xw + g;
    }
};

} // namespace

ClusterHull::ClusterHull(const RayCluster& c) : box_(cluster_box(c)) {
    Vec3 d{c.direction[0].mid(), c.direction[1].mid(), c.direction[2].mid()};
    if (norm(d) == 0) d = {0, 0, 1};
    d = normalize(d);
    const Vec3 seed = std::abs(d.x) < 0.6 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    axis_[0] = normalize(cross(d, seed));
    axis_[1] = cross(d, axis_[0]);
    for (int k = 0; k < 2; ++k) proj_[k] = project_cluster(c, axis_[k]);
}

bool ClusterHull::may_meet(const Box3& b) const {
    if (!b.overlaps(box_)) return false;
    for (int k = 0; k < 2; ++k) {
        // Interval(0) + sum of Interval(a) * Interval(lo, hi) over the axes,
        // with the product's sign case known from a (finite, as the box's
        // bounds are): the same bounds as the interval operations.
        double lo = 0, hi = 0;
        for (int i = 0; i < 3; ++i) {
            const double a = axis_[k][i];
            const bool up = a >= 0;
            lo = next_down(lo + next_down(a * (up ? b.lo[i] : b.hi[i])));
            hi = next_up(hi + next_up(a * (up ? b.hi[i] : b.lo[i])));
        }
        if (hi < proj_[k].lo() || lo > proj_[k].hi()) return false;
    }
    return true;
}

namespace {

// may_hit_triangle's separating axis: the triangle's normal. false when the
// hull of the rays' end boxes projects off the triangle's projection.
bool normal_axis_may_meet(const RayCluster& c, Vec3 T1, Vec3 T2, Vec3 T3) {
    // The rays' points lie in the convex hull of their two end boxes, so if
    // that hull's projection misses the triangle's, no ray meets it. Any axis
    // is valid, so the rounded normal is as good as the exact one.
    const Vec3 n = cross(T2 - T1, T3 - T1);
    auto project = [&](Vec3 p) {
        return Interval(n.x) * Interval(p.x) + Interval(n.y) * Interval(p.y) +
               Interval(n.z) * Interval(p.z);
    };
    const Interval tri = hull(hull(project(T1), project(T2)), project(T3));
    const Interval rays = project_cluster(c, n);
    return !(rays.hi() < tri.lo() || rays.lo() > tri.hi());
}

// may_hit_triangle's contraction of the system (Theorem 6: empty, no zero).
bool system_may_meet(const RayCluster& c, const TriangleSystem& sys) {
    IVec<3> x;
    x[0] = Interval(0.0, 1.0);
    x[1] = Interval(0.0, 1.0);
    x[2] = c.q - Interval(sys.qt);
    for (int iter = 0; iter < 4; ++iter) {
        const IVec<3> h = sys.step(x);
        if (h.is_empty()) return false;
        const IVec<3> y = intersect(h, x);
        if (y.is_empty()) return false;
        if (y[0].lo() + y[1].lo() > 1.0) return false; // beta + delta <= 1
        const bool progress = y[0].width() < 0.9 * x[0].width() ||
                              y[1].width() < 0.9 * x[1].width() ||
                              y[2].width() < 0.9 * x[2].width();
        x = y;
        if (!progress) break;
    }
    return true;
}

// covers_triangle on a built system.
bool system_covers(const RayCluster& c, const TriangleSystem& sys, Interval& q, Interval* beta,
                   Interval* delta) {
    if (!sys.preconditioned) return false;
    // Start from the whole triangle's parameter box widened a little (epsilon
    // inflation), so that H can land strictly inside it.
    IVec<3> x;
    x[0] = Interval(-0.1, 1.1);
    x[1] = Interval(-0.1, 1.1);
    x[2] = c.q - Interval(sys.qt);
    for (int iter = 0; iter < 6; ++iter) {
        const IVec<3> h = sys.step(x);
        if (h.is_empty()) return false;
        if (contains_in_interior(x, h)) {
            // Theorem 6 iii for every ray: one meeting point, with parameters in h.
            const bool inside = h[0].lo() > 0 && h[1].lo() > 0 && (h[0] + h[1]).hi() < 1;
            q = h[2] + Interval(sys.qt);
            if (beta) *beta = h[0];
            if (delta) *delta = h[1];
            return inside;
        }
        const IVec<3> y = intersect(h, x);
        if (y.is_empty()) return false;
        // The operator is a function of x: an x it leaves unchanged would give
        // the same h, which failed, in every remaining step.
        if (y[0] == x[0] && y[1] == x[1] && y[2] == x[2]) return false;
        x = y;
    }
    return false;
}

} // namespace

bool may_cover_triangle(const RayCluster& c, Vec3 T1, Vec3 T2, Vec3 T3) {
    // The ray O + q D meets T1 + beta E1 + delta E2 where (Moller-Trumbore)
    // beta = S.P / det, delta = D.Q / det with P = D x E2, det = E1.P,
    // S = O - T1, Q = S x E1; signs are compared instead of dividing.
    Interval O[3], D[3], E1[3], E2[3], S[3];
    for (int i = 0; i < 3; ++i) {
        O[i] = Interval(c.origin[i].mid());
        D[i] = Interval(c.direction[i].mid());
        if (!O[i].is_finite() || !D[i].is_finite()) return true;
        E1[i] = Interval(T2[i]) - Interval(T1[i]);
        E2[i] = Interval(T3[i]) - Interval(T1[i]);
        S[i] = O[i] - Interval(T1[i]);
    }
    const Interval P[3] = {D[1] * E2[2] - D[2] * E2[1], D[2] * E2[0] - D[0] * E2[2],
                           D[0] * E2[1] - D[1] * E2[0]};
    const Interval Q[3] = {S[1] * E1[2] - S[2] * E1[1], S[2] * E1[0] - S[0] * E1[2],
                           S[0] * E1[1] - S[1] * E1[0]};
    Interval det = E1[0] * P[0] + E1[1] * P[1] + E1[2] * P[2];
    Interval a = S[0] * P[0] + S[1] * P[1] + S[2] * P[2];
    Interval b = D[0] * Q[0] + D[1] * Q[1] + D[2] * Q[2];
    if (det.hi() < 0) {
        det = -det;
        a = -a;
        b = -b;
    } else if (!(det.lo() > 0)) {
        return true; // the ray may be parallel to the triangle's plane
    }
    // beta < 0, delta < 0 or beta + delta > 1: the ray misses.
    return !(a.hi() < 0 || b.hi() < 0 || (a + b - det).lo() > 0);
}

bool may_hit_triangle(const RayCluster& c, Vec3 T1, Vec3 T2, Vec3 T3) {
    return normal_axis_may_meet(c, T1, T2, T3) && system_may_meet(c, TriangleSystem(c, T1, T2, T3));
}

bool covers_triangle(const RayCluster& c, Vec3 T1, Vec3 T2, Vec3 T3, Interval& q, Interval* beta,
                     Interval* delta) {
    return system_covers(c, TriangleSystem(c, T1, T2, T3), q, beta, delta);
}

TriangleMeeting meet_triangle(const RayCluster& c, Vec3 T1, Vec3 T2, Vec3 T3, Interval& q,
                              Interval* beta, Interval* delta) {
    if (!normal_axis_may_meet(c, T1, T2, T3)) return TriangleMeeting::miss;
    const TriangleSystem sys(c, T1, T2, T3);
    if (!system_may_meet(c, sys)) return TriangleMeeting::miss;
    return may_cover_triangle(c, T1, T2, T3) && system_covers(c, sys, q, beta, delta)
               ? TriangleMeeting::covers
               : TriangleMeeting::may;
}

namespace {

using namespace interval3;

// x and y certainly of the same strict sign.
bool same_side(Interval x, Interval y) {
    return (x.lo() > 0 && y.lo() > 0) || (x.hi() < 0 && y.hi() < 0);
}

} // namespace

ApexTriangle apex_triangle(Vec3 apex, Vec3 T1, Vec3 T2, Vec3 T3) {
    ApexTriangle p;
    p.apex = apex;
    p.T1 = T1;
    const IV3 L = iv(apex), A = iv(T1), B = iv(T2), C = iv(T3);
    p.normal = icross(isub(B, A), isub(C, A));
    p.apex_side = idot(p.normal, isub(L, A));
    const IV3 V[3] = {A, B, C};
    for (int e = 0; e < 3; ++e) {
        const IV3 &P = V[e], &Q = V[(e + 1) % 3], &R = V[(e + 2) % 3];
        p.side[e] = icross(isub(P, L), isub(Q, L));
        p.inner[e] = idot(p.side[e], isub(R, L));
    }
    return p;
}

bool pyramid_may_meet_triangle(const ApexTriangle& p, const IVec<3>& ends) {
    const IV3 E{ends[0], ends[1], ends[2]};
    // The triangle's plane: apex and every end point strictly on one side.
    if (same_side(p.apex_side, idot(p.normal, isub(E, iv(p.T1))))) return false;
    // The apex itself lies on every side plane: only when it is certainly off
    // the triangle's plane is it outside the triangle, and the box strictly
    // beyond a side plane puts every other point of the hull outside too.
    if (p.apex_side.contains(0.0)) return true;
    // The side planes through the apex: the box strictly outside one of them
    // (the linear form's range over the box is exact up to rounding: each
    // coordinate of E enters once).
    const IV3 EL = isub(E, iv(p.apex));
    for (int e = 0; e < 3; ++e) {
        const Interval inner = p.inner[e], box = idot(p.side[e], EL);
        if ((inner.lo() > 0 && box.hi() < 0) || (inner.hi() < 0 && box.lo() > 0)) return false;
    }
    return true;
}

bool pyramid_may_meet_triangle(Vec3 apex, const IVec<3>& ends, Vec3 T1, Vec3 T2, Vec3 T3) {
    return pyramid_may_meet_triangle(apex_triangle(apex, T1, T2, T3), ends);
}

} // namespace seamless
