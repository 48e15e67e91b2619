// SPDX-License-Identifier: MIT
// Pinhole camera and the projection of the scene into the image plane (paper
// section 7, INTRACY step 1): in camera coordinates (X right, Y down, Z forward;
// right-handed) the primary ray through screen point (a, b) is {Z (a, b, 1)}, so a surface
// point lies on it iff X - a Z = 0 and Y - b Z = 0. For a sub-screen the
// cluster is the box [a] x [b], and the problem is two-dimensional (Theorem 10).
#pragma once

#include <seamless/base/vec.h>
#include <seamless/render/scene/scene.h>

#include <cmath>

namespace seamless {

struct CameraFrame {
    Vec3 eye, right, up, forward; // world-space orthonormal frame; camera Y = -up
    double tan_half;              // tan(fov/2): screen half-height at Z = 1
    double aspect;                // width / height
    int width, height;

    explicit CameraFrame(const Camera& c)
        : eye(c.eye), tan_half(std::tan(0.5 * c.fov_deg * M_PI / 180.0)),
          aspect(static_cast<double>(c.width) / c.height), width(c.width), height(c.height) {
        forward = normalize(c.look_at - c.eye);
        right = normalize(cross(forward, c.up));
        up = cross(right, forward);
    }
    // Screen coordinate a at horizontal pixel position x (pixel column k spans
    // [k, k+1); its centre is k + 0.5); columns run left to right.
    double screen_a(double x) const { return (2.0 * x / width - 1.0) * tan_half * aspect; }
    // Screen coordinate b of pixel row y (rows run top to bottom, as camera Y).
    double screen_b(double y) const { return (2.0 * y / height - 1.0) * tan_half; }
    // World-space point in camera coordinates.
    Vec3 to_camera(Vec3 p) const {
        Vec3 d = p - eye;
        return {dot(d, right), -dot(d, up), dot(d, forward)};
    }
    // Homogeneous point (w x, w y, w z, w) in camera coordinates (linear in it).
    HPoint to_camera(HPoint h) const {
        Vec3 d = h.xyz() - h.w * eye;
        return {dot(d, right), -dot(d, up), dot(d, forward), h.w};
    }
    // Camera coordinates back to world space (the frame is orthonormal and
    // right-handed, so normals map like directions).
    Vec3 to_world_direction(Vec3 c) const { return c.x * right - c.y * up + c.z * forward; }
    Vec3 to_world(Vec3 c) const { return eye + to_world_direction(c); }
    // World-space direction of the primary ray through screen point (a, b).
    Vec3 ray_direction(double a, double b) const { return forward + a * right - b * up; }
};

} // namespace seamless
