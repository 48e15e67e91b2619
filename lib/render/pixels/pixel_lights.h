// SPDX-License-Identifier: MIT
// SHADE step 2 for the pixels of a small sub-screen (INTRACY step 6, paper
// section 7): the hits of its pixels on one patch share one cluster of rays
// per light, from the light to the hull of those points (Proposition 11 with
// remarks 1-2, as cluster SHADE's lights in cluster_shade.h). Where no
// triangle but the patch's own may meet that cluster, the light reaches every
// one of the points, and their pixels trace no shadow ray to it.
#pragma once

#include <seamless/render/scene/scene.h>
#include <seamless/render/tray/ray_cluster.h>
#include <seamless/render/tray/trace.h>

namespace seamless {

// lit[l] (one per scene light) = 1 when light l certainly reaches every point
// of the world-space box Pw on patch `patch`: no triangle of another patch
// meets any segment from the light to a point of Pw (so a shadow ray from
// such a point, which skips the patch's own triangles, meets nothing); 0 when
// that is not proved (the pixel traces its shadow ray) or the light is off.
// hints[l]: a triangle that may have blocked light l for an earlier box (-1:
// none), tried first; set to the one that may block this box. A hint only:
// lit is the same for any hints.
void lights_reaching_box(const Scene& scene, const TriangleScene& ts, const IVec<3>& Pw, int patch,
                         char* lit, int* hints);

} // namespace seamless
