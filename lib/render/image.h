// SPDX-License-Identifier: MIT
// RGB framebuffer of quantised intensity levels and its PNG output (stb).
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace seamless {

struct Image {
    int width = 0, height = 0, levels = 16;
    // level per channel, row-major, 3 per pixel, row 0 at the top
    std::vector<std::uint16_t> level;
    // per pixel: 1 where a surface was painted, 0 where background
    std::vector<std::uint8_t> surface;

    Image() = default;
    Image(int w, int h, int lv)
        : width(w), height(h), levels(lv), level(static_cast<size_t>(w) * h * 3, 0),
          surface(static_cast<size_t>(w) * h, 0) {}
    std::uint8_t& surface_at(int x, int y) { return surface[static_cast<size_t>(y) * width + x]; }
    std::uint8_t surface_at(int x, int y) const {
        return surface[static_cast<size_t>(y) * width + x];
    }
    std::uint16_t& at(int x, int y, int c) {
        return level[(static_cast<size_t>(y) * width + x) * 3 + c];
    }
    std::uint16_t at(int x, int y, int c) const {
        return level[(static_cast<size_t>(y) * width + x) * 3 + c];
    }
};

// Level k of `levels` as an 8-bit value: round(255 k / (levels - 1)).
std::uint8_t level_to_byte(int k, int levels);

// Writes the image as 8-bit RGB PNG through a temporary file (no partial file on failure).
void write_png(const std::filesystem::path& path, const Image& image);

} // namespace seamless
