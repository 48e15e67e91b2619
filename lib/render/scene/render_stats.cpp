// SPDX-License-Identifier: MIT
#include <seamless/render/scene/render_stats.h>

namespace seamless {

void RenderStats::merge(const RenderStats& o) {
    for (const auto& [size, n] : o.subscreens_by_size) subscreens_by_size[size] += n;
    subscreens += o.subscreens;
    single_pixels += o.single_pixels;
    pixel_patch_solves += o.pixel_patch_solves;
    pixel_newton_certified += o.pixel_newton_certified;
    hs_iterations += o.hs_iterations;
    primary_rays += o.primary_rays;
    background_pixels += o.background_pixels;
    secondary_clusters += o.secondary_clusters;
    shadowed_clusters += o.shadowed_clusters;
    range_enclosures += o.range_enclosures;
    hs_steps += o.hs_steps;
    marks_narrowed += o.marks_narrowed;
    mark_bisections += o.mark_bisections;
    narrow_seconds += o.narrow_seconds;
    certify_seconds += o.certify_seconds;
    shade_seconds += o.shade_seconds;
    secondary_seconds += o.secondary_seconds;
    single_pixel_seconds += o.single_pixel_seconds;
    nearest_by_plane += o.nearest_by_plane;
    lights_blocked_by_surface += o.lights_blocked_by_surface;
    second_order_attempts += o.second_order_attempts;
    second_order_painted += o.second_order_painted;
    second_order_pixels += o.second_order_pixels;
    certified_pixel_fallbacks += o.certified_pixel_fallbacks;
    certified_pixel_seconds += o.certified_pixel_seconds;
    for (int i = 0; i < split_causes; ++i) {
        attempts_failed[i] += o.attempts_failed[i];
        single_pixels_by_cause[i] += o.single_pixels_by_cause[i];
        certified_pixels_by_cause[i] += o.certified_pixels_by_cause[i];
    }
}

} // namespace seamless
