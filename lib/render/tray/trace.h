// SPDX-License-Identifier: MIT
// Single rays against the triangles of the crack-free tessellation, and the
// recursive SHADE of paper section 7 for one ray: shadow rays to the lights,
// reflected and refracted rays (Whitted 1980), found through the binary patch
// trees (Proposition 11, remarks 1-2). Used by TRAY (section 8) for every ray
// and by INTRACY for single pixels and corner rays. Everything in world space.
#pragma once

#include <seamless/base/vec.h>
#include <seamless/render/scene/scene.h>
#include <seamless/render/tray/flat_patch_trees.h>
#include <seamless/render/tray/light_planes.h>
#include <seamless/render/tray/ray_cluster.h>
#include <seamless/render/tray/root_hierarchy.h>
#include <seamless/tessellate/tessellation.h>

#include <array>
#include <type_traits>
#include <vector>

namespace seamless {

// The crack-free tessellation of a scene with its binary patch trees
// (Proposition 11, remark 2) and per-triangle material and Bezier patch, for
// secondary rays.
struct TriangleScene {
    Tessellation tess;
    // triangle_material: #F index into Scene::materials.
    std::vector<int> triangle_material;
    // triangle_patch: #F index of the Bezier patch = tree root index, in the
    // order of bezier_patches(scene.model).
    std::vector<int> triangle_patch;
    // Hierarchy over the patch trees' roots for shadow rays (any_hit); empty:
    // the roots one after another.
    RootHierarchy root_hierarchy;
    // tess.trees laid out for the hull comparisons of rays and clusters.
    FlatPatchTrees flat_trees;
    // Secondary rays start this far (model units) from their surface point, so
    // that rounding never lets a ray meet the triangles it leaves from.
    // build_triangle_scene sets 1e-6 d_max.
    double ray_epsilon = 0;
    // apex_triangle(light l, triangle f) for the shadow pyramids of SHADE
    // step 2, formed on first use (light_planes.h; add_light_planes); empty:
    // none kept, each test forms its own.
    LightPlanes light_planes;
};

// Makes room in ts.light_planes for the scene's lights (INTRACY, once per
// render); the planes are formed as the render first needs them.
void add_light_planes(const Scene& scene, TriangleScene& ts);

// pyramid_may_meet_triangle from light l (at `apex`, scene.lights[l].position)
// over the box `ends` against triangle f, with ts.light_planes when formed.
bool light_pyramid_may_meet(const TriangleScene& ts, int l, Vec3 apex, const IVec<3>& ends, int f);

// Whether SHADE needs secondary rays for this scene: a light that is on and a
// used material with a diffuse or specular term (shadow rays), or a used
// material that reflects or transmits. Without them no triangles are built.
bool needs_secondary_rays(const Scene& scene);

// tessellate(scene.model) with the default tolerances (section 8), on
// `threads` workers (0: every core; the same triangles on any).
TriangleScene build_triangle_scene(const Scene& scene, int threads = 0);
// The same from the model's Bezier patches already extracted
// (bezier_patches(scene.model)), which INTRACY's step 1 uses too.
TriangleScene build_triangle_scene(const Scene& scene, const std::vector<BezierPatch>& patches,
                                   int threads);

struct TraceHit {
    int triangle = -1;
    double t = 0;
    Vec3 point;
    Vec3 normal; // interpolated exact corner normals, unit, oriented as the surface's (u,v)
    int material = -1;
    int patch = -1;
};

// The points origin + t dir with t in (t_min, t_max); the triangles of patch
// `skip_patch` (>= 0) are not tested (SHADE step 1: the marked patch, which
// keeps a point from shadowing itself).
struct TraceRay {
    Vec3 origin, dir;
    double t_min, t_max;
    int skip_patch = -1;
};

// The ray's nearest hit. Ties keep the first triangle in the fixed traversal
// order. `tests` (optional) counts ray-triangle tests.
bool nearest_hit(const TriangleScene& ts, const TraceRay& ray, TraceHit& hit,
                 long long* tests = nullptr);

// Any hit of the ray (shadow rays; stops at the first). With `blocker` (a
// shadow cache entry, Haines and Greenberg 1986), the triangle *blocker (when
// it is one of ts's and not on skip_patch) is tested first, and the triangle
// found is stored there: a hint only, the answer is the same.
bool any_hit(const TriangleScene& ts, const TraceRay& ray, long long* tests = nullptr,
             int* blocker = nullptr);

// SHADE step 2 for one ray: into `lighting` (its ambient and the lights that
// reach P), every light that is on, in front of the surface (Nf: the normal
// turned towards the viewer) and not blocked: blocked(dir, dist) says whether
// the unit-direction ray from P meets something within dist. No shadow ray at
// all when the material has no diffuse or specular term. One home for TRAY's
// rule, so the benchmark's Embree renderer shades exactly as TRAY does.
template <class Blocked>
void lights_reaching(const Scene& scene, const Material& m, Vec3 P, Vec3 Nf, Scene& lighting,
                     Blocked&& blocked) {
    lighting.ambient = scene.ambient;
    lighting.lights.clear();
    if (m.diffuse == 0 && m.specular == 0) return;
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const Light& light = scene.lights[i];
        if (!light.on()) continue;
        const Vec3 L = light.position - P;
        if (!(dot(Nf, L) > 0)) continue;
        const double dist = norm(L);
        bool b;
        if constexpr (std::is_invocable_v<Blocked&, Vec3, double, int>)
            b = blocked(L / dist, dist, static_cast<int>(i));
        else
            b = blocked(L / dist, dist);
        if (!b) lighting.lights.push_back(light);
    }
}

// A point SHADE shades: surface point P with unit normal N of material
// `material` on Bezier patch `patch`, seen from unit direction `view` (from P
// towards the viewer).
struct ShadePoint {
    Vec3 P, N;
    int material, patch;
    Vec3 view;
};

// SHADE for one ray (section 7): intensity per channel in [0, 1] at `at`, at
// recursion depth `depth` (0 at the primary hit). Ambient; per light that is on and in
// front of the surface, a shadow ray (step 2); the local terms by shade<double>
// with the visible lights (the illumination model of INTRACY); then
// reflect * the reflected ray and transmit * the refracted ray (steps 3-4, up
// to scene.max_depth; the background where they hit nothing). lit
// (optional, one per light): lit[l] != 0 where light l is known to reach P
// (a certificate for many points, pixel_lights.h): no shadow ray to it.
std::array<double, 3> shade_ray(const Scene& scene, const TriangleScene& ts, const ShadePoint& at,
                                int depth, long long* tests = nullptr, const char* lit = nullptr);

} // namespace seamless
