// SPDX-License-Identifier: MIT
// What a render is asked for (RenderOptions, one home per default) and by
// which method: INTRACY (paper section 7), TRAY (section 8) or the per-pixel
// reference.
#pragma once

#include <functional>

namespace seamless {

enum class RenderMethod { intracy, tray, reference };

struct RenderOptions {
    RenderMethod method = RenderMethod::intracy;
    int width = 0, height = 0; // 0: the scene camera's size
    int levels = 0;            // 0: the scene's levels
    int threads = 0;           // 0: every core; 1: sequential. The image is the same either way.
    // Step 9 with remark 2 (bilinear form plus dither); false: no dither, B is
    // painted when its enclosure holds one level per channel, or by the
    // second-order rule (second_order.h) with every level within one of the truth.
    bool dither = true;
    int prepartition = 8; // remark 4: the screen is prepartitioned into 8 x 8 parts
    // INTRACY: a sub-screen of at most this many pixels is solved pixel by
    // pixel (certified Newton) without a cluster attempt; 1: never. 20 (the
    // 5 x 4 sub-screens of 640 x 480's quadtree) took the fewest instructions
    // on the teapot and scene 3 (docs/results/render.md).
    int pixel_subscreen = 20;
    // INTRACY: a B whose step 7 certificate holds while SHADE (a light) or
    // step 9 (span) fails is painted one ray per pixel from the certificate
    // (certified_pixels.h) instead of split, up to a size; false: always split.
    bool certified_pixels = true;
    // Called with the fraction done (0..1), from any thread, at most a few hundred times.
    std::function<void(double)> progress;
};

} // namespace seamless
