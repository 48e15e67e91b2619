// SPDX-License-Identifier: MIT
// One ray against boxes and triangles, for TRAY (paper section 8) and the
// single-ray case of Proposition 11: a slab test for the hull comparison of
// remark 1 (conservative, so a hull never drops a triangle the ray hits) and
// the watertight ray-triangle test of Woop, Benthin and Wald (JCGT 2013): the
// edge functions of an edge are computed from the same sheared vertex
// coordinates in both triangles that share it, and zero counts as inside, so a
// ray through a shared edge or vertex hits at least one of the triangles.
#pragma once

#include <seamless/base/vec.h>

#include <limits>
#include <utility>

namespace seamless {

// A ray o + t d (t > 0), prepared for many box and triangle tests.
struct TriangleRay {
    Vec3 origin, dir;
    Vec3 inv_dir; // 1 / d per axis (+-inf where d is 0)
    // Woop et al.: kz the axis of largest |d|, kx and ky the others (swapped so
    // the winding is kept), and the shear that maps d onto the kz axis.
    int kx = 0, ky = 1, kz = 2;
    double sx = 0, sy = 0, sz = 1;
    // Slab test: true when every 1 / d is finite and nonzero d (no NaN can
    // arise); then far_hi[i] says whether the slab is left at hi (d > 0).
    bool finite_slabs = false;
    bool far_hi[3] = {true, true, true};

    TriangleRay(Vec3 o, Vec3 d);
};

// Parameter interval [t0, t1] of the ray inside `box` intersected with
// [0, t_max]; false when empty. Robust for axis-parallel rays (a zero direction
// component tests the origin against the slab) and widened by a few ulps
// (pbrt's 1 + 2 gamma(3)), so rounding never loses a grazing hit. Inline: a
// shadow ray tests tens of boxes, and the call cost more than the test.
inline bool ray_hits_box(const TriangleRay& ray, const Box3& box, double t_max) {
    // pbrt-v4: t1 *= 1 + 2 gamma(3) makes the slab test conservative.
    constexpr double eps = std::numeric_limits<double>::epsilon() * 0.5;
    constexpr double widen = 1 + 2 * (3 * eps) / (1 - 3 * eps);
    double t0 = 0, t1 = t_max;
    if (ray.finite_slabs) {
        // The entry and exit of each slab known from the sign of d (rounding
        // is monotone), and t0 only grows and t1 only shrinks, so one
        // comparison at the end decides as the loop below: fewer branches.
        for (int i = 0; i < 3; ++i) {
            const double o = ray.origin[i], inv = ray.inv_dir[i];
            const double tn = ((ray.far_hi[i] ? box.lo[i] : box.hi[i]) - o) * inv;
            const double tf = ((ray.far_hi[i] ? box.hi[i] : box.lo[i]) - o) * inv * widen;
            t0 = tn > t0 ? tn : t0;
            t1 = tf < t1 ? tf : t1;
        }
        return !(t0 > t1);
    }
    for (int i = 0; i < 3; ++i) {
        const double o = ray.origin[i], lo = box.lo[i], hi = box.hi[i];
        if (ray.dir[i] == 0) {
            // Parallel to the slab: (lo - o) * inf would be NaN when o lies on it.
            if (o < lo || o > hi) return false;
            continue;
        }
        double tn = (lo - o) * ray.inv_dir[i], tf = (hi - o) * ray.inv_dir[i];
        if (tn > tf) std::swap(tn, tf);
        tf *= widen;
        t0 = tn > t0 ? tn : t0;
        t1 = tf < t1 ? tf : t1;
        if (t0 > t1) return false;
    }
    return true;
}

struct RayTriangleHit {
    double t = 0;
    double b0 = 0, b1 = 0, b2 = 0; // barycentric weights of the corners p0, p1, p2
};

// Watertight test; true and `hit` when the ray meets the triangle at t in
// (0, t_max). Degenerate (zero-area as seen along the ray) triangles are missed.
bool intersect_triangle(const TriangleRay& ray, Vec3 p0, Vec3 p1, Vec3 p2, double t_max,
                        RayTriangleHit& hit);

} // namespace seamless
