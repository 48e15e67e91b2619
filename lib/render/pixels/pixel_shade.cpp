// SPDX-License-Identifier: MIT
// SHADE for one primary ray at an exact hit (pixel_shade.h).
#include <seamless/render/pixels/pixel_shade.h>

#include <seamless/render/shading/shading.h>

namespace seamless {

std::array<double, 3> shade_hit(const ProjectedScene& ps, const Scene& scene,
                                const TriangleScene* ts, const PixelHit& h) {
    Vec3 P, N;
    surface_frame(ps.patches[h.patch].patch, h.s, h.t, P, N);
    return shade_at(ps, scene, ts, h.patch, P, N);
}

// The local model without secondary rays, else shade_ray of trace.h in world space.
std::array<double, 3> shade_at(const ProjectedScene& ps, const Scene& scene,
                               const TriangleScene* ts, int patch, Vec3 P, Vec3 N,
                               const char* lit) {
    const ProjectedPatch& pp = ps.patches[patch];
    if (!ts)
        return shade<double>(ps.lighting, ps.lighting.materials[pp.material], to_v3(P), to_v3(N),
                             Vec3{});
    const Vec3 Pw = ps.frame.to_world(P);
    return shade_ray(scene, *ts,
                     {Pw, normalize(ps.frame.to_world_direction(N)), pp.material, patch,
                      normalize(ps.frame.eye - Pw)},
                     0, nullptr, lit);
}

} // namespace seamless
