// SPDX-License-Identifier: MIT
// Rendering a scene: INTRACY (paper section 7: screen subdivision with interval
// enclosures of the intensity), TRAY (section 8: one ray per pixel against the
// triangles of the crack-free tessellation through binary patch trees) and the
// per-pixel exact reference (Hansen-Sengupta on the patches for every pixel).
#pragma once

#include <seamless/render/scene/image.h>
#include <seamless/render/scene/render_options.h>
#include <seamless/render/scene/render_stats.h>
#include <seamless/render/scene/scene.h>

namespace seamless {

Image render(const Scene& scene, const RenderOptions& options, RenderStats* stats = nullptr);

// The three methods behind render().
Image render_intracy(const Scene& scene, const RenderOptions& options, RenderStats& stats);
Image render_tray(const Scene& scene, const RenderOptions& options, RenderStats& stats);
Image render_reference(const Scene& scene, const RenderOptions& options, RenderStats& stats);

} // namespace seamless
