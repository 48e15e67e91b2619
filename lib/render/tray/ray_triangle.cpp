// SPDX-License-Identifier: MIT
#include <seamless/render/tray/ray_triangle.h>

#include <cmath>
#include <limits>
#include <utility>

namespace seamless {

TriangleRay::TriangleRay(Vec3 o, Vec3 d) : origin(o), dir(d) {
    inv_dir = {1.0 / d.x, 1.0 / d.y, 1.0 / d.z};
    finite_slabs = true;
    for (int i = 0; i < 3; ++i) {
        finite_slabs = finite_slabs && d[i] != 0 && std::isfinite(inv_dir[i]);
        far_hi[i] = !(d[i] < 0);
    }
    const Vec3 a{std::abs(d.x), std::abs(d.y), std::abs(d.z)};
    kz = a.x >= a.y ? (a.x >= a.z ? 0 : 2) : (a.y >= a.z ? 1 : 2);
    kx = (kz + 1) % 3;
    ky = (kx + 1) % 3;
    if (d[kz] < 0) std::swap(kx, ky);
    sx = d[kx] / d[kz];
    sy = d[ky] / d[kz];
    sz = 1.0 / d[kz];
}

bool intersect_triangle(const TriangleRay& ray, Vec3 p0, Vec3 p1, Vec3 p2, double t_max,
                        RayTriangleHit& hit) {
    const Vec3 A = p0 - ray.origin, B = p1 - ray.origin, C = p2 - ray.origin;
    // Shear and scale so the ray runs along +z from the origin.
    const double ax = A[ray.kx] - ray.sx * A[ray.kz], ay = A[ray.ky] - ray.sy * A[ray.kz];
    const double bx = B[ray.kx] - ray.sx * B[ray.kz], by = B[ray.ky] - ray.sy * B[ray.kz];
    const double cx = C[ray.kx] - ray.sx * C[ray.kz], cy = C[ray.ky] - ray.sy * C[ray.kz];
    // Edge functions; zero is inside on both sides of an edge.
    const double u = cx * by - cy * bx;
    const double v = ax * cy - ay * cx;
    const double w = bx * ay - by * ax;
    if ((u < 0 || v < 0 || w < 0) && (u > 0 || v > 0 || w > 0)) return false;
    const double det = u + v + w;
    if (det == 0) return false;
    const double az = ray.sz * A[ray.kz], bz = ray.sz * B[ray.kz], cz = ray.sz * C[ray.kz];
    const double T = u * az + v * bz + w * cz;
    // 0 < T / det < t_max without dividing.
    if (det > 0 ? (T <= 0 || T >= t_max * det) : (T >= 0 || T <= t_max * det)) return false;
    const double inv = 1.0 / det;
    hit.t = T * inv;
    hit.b0 = u * inv;
    hit.b1 = v * inv;
    hit.b2 = w * inv;
    return true;
}

} // namespace seamless
