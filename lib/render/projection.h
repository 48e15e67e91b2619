// SPDX-License-Identifier: MIT
// INTRACY step 1, precalculation: the scene's Bezier patches in camera
// coordinates with their power forms, and the lights in camera coordinates, so
// that primary rays pose the two-dimensional problem of Theorem 10.
#pragma once

#include <seamless/render/camera.h>
#include <seamless/render/scene.h>
#include <seamless/spline/enclosure.h>
#include <seamless/spline/ray_patch.h>
#include <seamless/spline/subpatch.h>

#include <vector>

namespace seamless {

struct ProjectedPatch {
    BezierPatch patch; // homogeneous control points in camera coordinates
    PatchForms forms;  // power forms of `patch` (section 4)
    PatchForms world;  // power forms of the patch in world coordinates (SHADE's
                       // light and secondary clusters: a world box of points
                       // straight from them, not a rotated camera box); only
                       // when the scene needs them (needs_secondary_rays)
    bool has_world = false;
    IVec3 hull;          // enclosure of the whole patch, camera coordinates
    SubpatchShape shape; // layout of its subpatches' coefficients (mark.h)
    int material = 0;
};

struct ProjectedScene {
    CameraFrame frame;
    std::vector<ProjectedPatch> patches;
    Scene lighting; // ambient, materials and lights (in camera coordinates); no model

    explicit ProjectedScene(const Camera& c) : frame(c) {}
    // The camera-space primary ray through screen point (a, b): origin 0, direction (a, b, 1).
    static Ray primary_ray(double a, double b) { return {{0, 0, 0}, {a, b, 1}}; }
};

// Builds the projected scene for an image of width x height pixels.
ProjectedScene project_scene(const Scene& scene, int width, int height);

// Surface point and normal of a patch at local (s, t), in camera coordinates,
// for shading; at a pole (vanishing normal) the normal is taken slightly inside.
void surface_frame(const BezierPatch& b, double s, double t, Vec3& point, Vec3& normal);

} // namespace seamless
