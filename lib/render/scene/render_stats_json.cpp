// SPDX-License-Identifier: MIT
#include <seamless/render/scene/render_stats_json.h>

#include <nlohmann/json.hpp>

namespace seamless {

namespace {

// INTRACY's failed step 7-9 attempts and single pixels by cause (RenderStats::SplitCause).
nlohmann::json split_causes_json(const RenderStats& st) {
    nlohmann::json j = nlohmann::json::object();
    for (int i = 0; i < RenderStats::split_causes; ++i)
        j[RenderStats::split_cause_names[i]] = {
            {"attempts_failed", st.attempts_failed[i]},
            {"single_pixels", st.single_pixels_by_cause[i]},
            {"certified_pixels", st.certified_pixels_by_cause[i]}};
    return j;
}

} // namespace

std::string render_stats_json(const RenderStats& st) {
    nlohmann::json sizes = nlohmann::json::object();
    for (const auto& [size, n] : st.subscreens_by_size) sizes[std::to_string(size)] = n;
    const nlohmann::json js{{"method", st.method},
                            {"width", st.width},
                            {"height", st.height},
                            {"levels", st.levels},
                            {"threads", st.threads},
                            {"seconds", st.seconds},
                            {"precalc_seconds", st.precalc_seconds},
                            {"patches", st.patches},
                            {"triangles", st.triangles},
                            {"subscreens", st.subscreens},
                            {"subscreens_by_size", sizes},
                            {"single_pixels", st.single_pixels},
                            {"single_pixel_fraction", st.single_pixel_fraction()},
                            {"hs_iterations_per_patch", st.hs_iterations_per_patch()},
                            {"patches_per_pixel", st.patches_per_pixel()},
                            {"primary_rays", st.primary_rays},
                            {"background_pixels", st.background_pixels},
                            {"secondary_clusters", st.secondary_clusters},
                            {"shadowed_clusters", st.shadowed_clusters},
                            {"range_enclosures", st.range_enclosures},
                            {"enclosures_per_pixel", st.enclosures_per_pixel()},
                            {"hs_steps", st.hs_steps},
                            {"marks_narrowed", st.marks_narrowed},
                            {"mark_bisections", st.mark_bisections},
                            {"pixel_patch_solves", st.pixel_patch_solves},
                            {"pixel_newton_certified", st.pixel_newton_certified},
                            {"split_causes", split_causes_json(st)},
                            {"nearest_by_plane", st.nearest_by_plane},
                            {"lights_blocked_by_surface", st.lights_blocked_by_surface},
                            {"second_order",
                             {{"attempts", st.second_order_attempts},
                              {"painted", st.second_order_painted},
                              {"pixels", st.second_order_pixels}}},
                            {"step_seconds",
                             {{"narrowing", st.narrow_seconds},
                              {"certificate", st.certify_seconds},
                              {"shade", st.shade_seconds},
                              {"secondary_clusters", st.secondary_seconds},
                              {"single_pixels", st.single_pixel_seconds},
                              {"certified_pixels", st.certified_pixel_seconds}}},
                            {"certified_pixel_fallbacks", st.certified_pixel_fallbacks}};
    return js.dump(2);
}

} // namespace seamless
