// SPDX-License-Identifier: MIT
// What a render counts (--stats, docs/formats.md): the paper's Table 3
// (sub-screens painted at once, by size), the work of each INTRACY step and
// why sub-screens split down to single pixels. Each part of the screen counts
// into its own RenderStats; merge() adds them up in part order.
#pragma once

#include <array>
#include <map>
#include <string>

namespace seamless {

struct RenderStats {
    std::string method;
    int width = 0, height = 0, levels = 0, threads = 0;
    double seconds = 0, precalc_seconds = 0;
    // Paper's Table 3: pixel count of each sub-screen painted at once -> how many.
    std::map<long long, long long> subscreens_by_size;
    long long subscreens = 0;         // sub-screens taken from the stacks
    long long single_pixels = 0;      // pixels solved as a one-pixel sub-screen
    long long pixel_patch_solves = 0; // single-ray Hansen-Sengupta solves (pixel x patch)
    long long pixel_newton_certified =
        0;                       // of those, decided without the covering method (pixel_solve.h)
    long long hs_iterations = 0; // Hansen-Sengupta steps in those solves
    long long primary_rays = 0;  // single rays traced (pixels and corner rays)
    long long background_pixels = 0;
    // INTRACY: mirror or glass sub-screens painted with certified reflected or
    // refracted clusters (SHADE steps 3.3-3.4 and 4), and sub-screens painted
    // with a light certainly blocked for the whole cluster (step 2).
    long long secondary_clusters = 0, shadowed_clusters = 0;
    long long patches = 0, triangles = 0;
    // INTRACY's cost: power-form range enclosures (enclosure.h, range_enclosure_count),
    // Hansen-Sengupta steps of every kind (pixel solves and cluster certificates),
    // and thread CPU seconds per step, summed over the parts (so over threads): step 3's
    // narrowing, step 7's certificate, step 8's SHADE (without its secondary
    // clusters), SHADE steps 3-4's secondary clusters, and step 6's single pixels.
    long long range_enclosures = 0, hs_steps = 0;
    long long marks_narrowed = 0,
              mark_bisections = 0; // step 3: Theorem 10 calls, covering bisections
    double narrow_seconds = 0, certify_seconds = 0, shade_seconds = 0, secondary_seconds = 0,
           single_pixel_seconds = 0;
    // INTRACY: why sub-screens split down to single pixels. Each failed step 7-9
    // attempt counts under its cause, and each pixel solved on its own (step 6, or
    // a B of at most pixel_subscreen pixels) under the cause that made its nearest
    // attempting ancestor split (SplitCause::none: no ancestor attempted).
    enum SplitCause {
        none,         // no step 7 attempt above it (e.g. a mark crossing the eye plane)
        seam,         // certificate failed, the marks hold several patches of one surface
        surfaces,     // certificate failed, patches of several surfaces marked (not all
                      // meeting at corners: silhouettes over another surface, overlaps)
        one_patch,    // certificate failed on the only marked patch (silhouette, fold)
        not_nearest,  // certified, but another patch is not q-separated (behind it)
        light,        // SHADE step 2: a light undecided for the cluster
        span,         // step 9: the intensity enclosure spans too many levels
        surface_seam, // certificate failed, patches of several surfaces marked, each
                      // sharing a corner with another (a seam between surfaces)
        split_causes
    };
    // The causes' names in --stats (docs/formats.md), in the enum's order.
    static constexpr const char* split_cause_names[split_causes] = {
        "none", "seam", "surfaces", "one_patch", "not_nearest", "light", "span", "surface_seam"};
    std::array<long long, split_causes> attempts_failed{}, single_pixels_by_cause{};
    // Step 7 certificates of "nearest" that needed a separating plane (depths of
    // another marked patch overlapping), and SHADE step 2 lights found blocked
    // by a surface of triangles rather than one.
    long long nearest_by_plane = 0, lights_blocked_by_surface = 0;
    // Step 9's second-order criterion (second_order.h), tried where the plain
    // test failed on span: attempts, sub-screens painted by it, and their pixels.
    long long second_order_attempts = 0, second_order_painted = 0, second_order_pixels = 0;
    // Pixels of a B whose step 7 certificate held while SHADE or step 9 failed
    // (cause light or span), painted from the certificate one ray each
    // (certified_pixels.h): per cause, those whose Newton did not converge in
    // the certified box (solved as step 6's), and their CPU seconds.
    std::array<long long, split_causes> certified_pixels_by_cause{};
    long long certified_pixel_fallbacks = 0;
    double certified_pixel_seconds = 0;

    double single_pixel_fraction() const {
        return width > 0 && height > 0
                   ? static_cast<double>(single_pixels) / (static_cast<double>(width) * height)
                   : 0;
    }
    double hs_iterations_per_patch() const {
        return pixel_patch_solves ? static_cast<double>(hs_iterations) / pixel_patch_solves : 0;
    }
    double patches_per_pixel() const {
        return single_pixels ? static_cast<double>(pixel_patch_solves) / single_pixels : 0;
    }
    double enclosures_per_pixel() const {
        return width > 0 && height > 0
                   ? static_cast<double>(range_enclosures) / (static_cast<double>(width) * height)
                   : 0;
    }
    void merge(const RenderStats& o);
};

} // namespace seamless
