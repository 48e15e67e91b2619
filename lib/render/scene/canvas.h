// SPDX-License-Identifier: MIT
// The image INTRACY paints (paper section 7), a sub-screen's pixels at a
// time: the background where no patch is hit (steps 4 and 5), an intensity
// quantised to the image's levels where one is (steps 6 to 9).
#pragma once

#include <seamless/base/vec.h>
#include <seamless/render/scene/image.h>
#include <seamless/render/scene/render_stats.h>
#include <seamless/render/shading/shading.h>

#include <array>
#include <cstdint>

namespace seamless {

// A sub-screen's pixels, inclusive.
struct PixelRect {
    int x0, y0, x1, y1;
    long long count() const { return static_cast<long long>(x1 - x0 + 1) * (y1 - y0 + 1); }
    bool empty() const { return x0 > x1 || y0 > y1; }
    bool operator==(const PixelRect&) const = default;
};

class Canvas {
  public:
    Canvas(Image& image, int levels, const Vec3& background) : image_(image), levels_(levels) {
        for (int c = 0; c < 3; ++c)
            background_[c] = static_cast<std::uint16_t>(quantise(background[c], levels));
    }
    Image& image() const { return image_; }
    int levels() const { return levels_; }

    // r painted background, counted in st.background_pixels.
    void background(const PixelRect& r, RenderStats& st) const {
        for (int y = r.y0; y <= r.y1; ++y)
            for (int x = r.x0; x <= r.x1; ++x)
                for (int c = 0; c < 3; ++c) image_.at(x, y, c) = background_[c];
        st.background_pixels += r.count();
    }
    // The strips of `outer` around `inner` (inside it) painted background.
    void background_around(const PixelRect& outer, const PixelRect& inner, RenderStats& st) const {
        if (inner.y0 > outer.y0) background({outer.x0, outer.y0, outer.x1, inner.y0 - 1}, st);
        if (inner.y1 < outer.y1) background({outer.x0, inner.y1 + 1, outer.x1, outer.y1}, st);
        if (inner.x0 > outer.x0) background({outer.x0, inner.y0, inner.x0 - 1, inner.y1}, st);
        if (inner.x1 < outer.x1) background({inner.x1 + 1, inner.y0, outer.x1, inner.y1}, st);
    }
    // Pixel (x, y) painted with intensity I, a surface's.
    void intensity(int x, int y, const std::array<double, 3>& I) const {
        for (int c = 0; c < 3; ++c)
            image_.at(x, y, c) = static_cast<std::uint16_t>(quantise(I[c], levels_));
        image_.surface_at(x, y) = 1;
    }

  private:
    Image& image_;
    int levels_;
    std::uint16_t background_[3];
};

} // namespace seamless
