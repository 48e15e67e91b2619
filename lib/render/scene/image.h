// SPDX-License-Identifier: MIT
// RGB framebuffer of quantised intensity levels and its PNG output (libpng).
#pragma once

#include <seamless/base/parallel/huge_pages.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <vector>

namespace seamless {

// std::allocator whose resize(n) leaves new elements uninitialised (default
// initialisation): fresh pages stay untouched until a pixel is written; its
// storage from allocate_huge (huge_pages.h: the image is written once per
// render, and its 4 KB pages' first touches cost ~26 ms of CPU at 1280x1024).
template <class T> struct UninitialisedAllocator : std::allocator<T> {
    template <class U> struct rebind { using other = UninitialisedAllocator<U>; };
    UninitialisedAllocator() = default;
    template <class U> UninitialisedAllocator(const UninitialisedAllocator<U>&) {}
    T* allocate(std::size_t n) { return static_cast<T*>(allocate_huge(n * sizeof(T))); }
    void deallocate(T* p, std::size_t n) { release_huge(p, n * sizeof(T)); }
    template <class U> void construct(U* p) { ::new (static_cast<void*>(p)) U; }
    template <class U, class... A> void construct(U* p, A&&... a) {
        ::new (static_cast<void*>(p)) U(std::forward<A>(a)...);
    }
};

struct Image {
    int width = 0, height = 0, levels = 16;
    // level per channel, row-major, 3 per pixel, row 0 at the top
    std::vector<std::uint16_t, UninitialisedAllocator<std::uint16_t>> level;
    // per pixel: 1 where a surface was painted, 0 where background
    std::vector<std::uint8_t, UninitialisedAllocator<std::uint8_t>> surface;

    Image() = default;
    // Every pixel level 0, background.
    Image(int w, int h, int lv) : Image(w, h, lv, Unfilled{}) { clear(0, 0, w - 1, h - 1); }
    // Pixels unwritten: the caller clears or paints every one (render_intracy
    // clears each part in its worker: the image's fresh pages are then first
    // touched on every thread instead of by one memset before the parts start).
    struct Unfilled {};
    Image(int w, int h, int lv, Unfilled) : width(w), height(h), levels(lv) {
        level.resize(static_cast<size_t>(w) * h * 3);
        surface.resize(static_cast<size_t>(w) * h);
    }
    // Pixels x0..x1 x y0..y1 (inclusive) to level 0, background.
    void clear(int x0, int y0, int x1, int y1);
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
