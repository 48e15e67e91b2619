// SPDX-License-Identifier: MIT
// TRAY (paper section 8): placeholder until the patch-tree ray tracer lands.
#include <seamless/base/error.h>
#include <seamless/render/render.h>

namespace seamless {

Image render_tray(const Scene& scene, const RenderOptions&, RenderStats&) {
    throw InputError(scene.source, "", "--method tray is not available yet");
}

} // namespace seamless
