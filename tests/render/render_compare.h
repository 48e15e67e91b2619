// SPDX-License-Identifier: MIT
// Comparing two renders pixel by pixel.
#pragma once

#include <seamless/render/render.h>
#include <seamless/render/scene/image.h>

#include <catch2/catch.hpp>

#include <cstdlib>

namespace seamless::test {

struct ImageComparison {
    long long pixels = 0;
    long long within_one = 0;                      // every channel within one level
    int max_difference = 0;                        // largest level difference of any channel
    long long surface_mismatch = 0;                // surface in one, background in the other
    long long surface_mismatch_off_silhouette = 0; // ... not next to a surface/background edge
    double fraction_within_one() const {
        return pixels ? static_cast<double>(within_one) / pixels : 0;
    }
};

// A pixel is next to a silhouette when one of its 8 neighbours (or itself) has
// a different surface flag in either image.
inline ImageComparison compare(const Image& a, const Image& b) {
    ImageComparison c;
    auto edge = [&](const Image& im, int x, int y) {
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                int u = x + dx, v = y + dy;
                if (u < 0 || v < 0 || u >= im.width || v >= im.height) continue;
                if (im.surface_at(u, v) != im.surface_at(x, y)) return true;
            }
        return false;
    };
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            ++c.pixels;
            int d = 0;
            for (int ch = 0; ch < 3; ++ch)
                d = std::max(d, std::abs(a.at(x, y, ch) - b.at(x, y, ch)));
            c.max_difference = std::max(c.max_difference, d);
            c.within_one += d <= 1;
            if (a.surface_at(x, y) != b.surface_at(x, y)) {
                ++c.surface_mismatch;
                if (!edge(a, x, y) && !edge(b, x, y)) ++c.surface_mismatch_off_silhouette;
            }
        }
    return c;
}

// Renders `scene` with one thread and with two: images and work counts agree.
inline void check_threads_agree(const Scene& scene, RenderMethod method, int width, int height) {
    RenderOptions o;
    o.method = method;
    o.width = width;
    o.height = height;
    o.threads = 1;
    RenderStats s1, s2;
    const Image a = render(scene, o, &s1);
    o.threads = 2;
    const Image b = render(scene, o, &s2);
    CHECK(a.level == b.level);
    CHECK(a.surface == b.surface);
    CHECK(s1.pixel_patch_solves == s2.pixel_patch_solves);
}

} // namespace seamless::test
