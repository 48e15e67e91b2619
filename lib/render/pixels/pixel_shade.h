// SPDX-License-Identifier: MIT
// SHADE for one primary ray at an exact hit (paper section 7): step 6's single
// pixels, the pixels of a certified cluster (certified_pixels.h) and step 9's
// corner rays. With secondary rays in play (ts not null), shadows, reflection
// and refraction are traced against the triangles (SHADE steps 2-4, trace.h);
// the local illumination model is the same either way.
#pragma once

#include <seamless/render/pixels/pixel_solve.h>
#include <seamless/render/scene/projection.h>
#include <seamless/render/scene/scene.h>
#include <seamless/render/tray/trace.h>

#include <array>

namespace seamless {

// SHADE at the hit h (h.patch >= 0).
std::array<double, 3> shade_hit(const ProjectedScene& ps, const Scene& scene,
                                const TriangleScene* ts, const PixelHit& h);
// The same at the hit's point P and normal N (camera coordinates,
// surface_frame of projection.h) on patch `patch`; lit: as shade_ray's (trace.h).
std::array<double, 3> shade_at(const ProjectedScene& ps, const Scene& scene,
                               const TriangleScene* ts, int patch, Vec3 P, Vec3 N,
                               const char* lit = nullptr);

} // namespace seamless
