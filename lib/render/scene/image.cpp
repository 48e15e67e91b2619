// SPDX-License-Identifier: MIT
#include <seamless/render/scene/image.h>

#include <seamless/base/error.h>
#include <seamless/base/files/atomic_file.h>

#include <png.h> // libpng: only this file

#include <algorithm>
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <vector>

namespace seamless {
namespace {

// libpng reports an error by a longjmp back to the setjmp below: no C++ object
// with a destructor lives in this frame, and nothing is printed (the caller
// throws one InputError line).
void png_failed(png_structp png, png_const_charp) {
    png_longjmp(png, 1);
}
void png_warned(png_structp, png_const_charp) {}

bool write_png_rows(std::FILE* f, int width, int height, png_bytepp rows) {
    png_structp png =
        png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, png_failed, png_warned);
    if (!png) return false;
    png_infop info = png_create_info_struct(png);
    if (!info) {
        png_destroy_write_struct(&png, nullptr);
        return false;
    }
    if (setjmp(png_jmpbuf(png))) { // the whole condition, as C requires of setjmp
        png_destroy_write_struct(&png, &info);
        return false;
    }
    png_init_io(png, f);
    png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8,
                 PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    // Every row with PNG's Sub filter: the images are regions of equal level,
    // which Sub turns into runs of zeros. zlib level 1: a fraction of level
    // 6's time for files under half as large again.
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
    png_set_compression_level(png, 1);
    png_write_info(png, info);
    png_write_image(png, rows);
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return true;
}

} // namespace

void Image::clear(int x0, int y0, int x1, int y1) {
    if (x1 < x0) return;
    for (int y = y0; y <= y1; ++y) {
        std::fill_n(&at(x0, y, 0), static_cast<size_t>(x1 - x0 + 1) * 3, std::uint16_t{0});
        std::fill_n(&surface_at(x0, y), x1 - x0 + 1, std::uint8_t{0});
    }
}

std::uint8_t level_to_byte(int k, int levels) {
    return static_cast<std::uint8_t>(std::lround(255.0 * k / (levels - 1)));
}

void write_png(const std::filesystem::path& path, const Image& im) {
    // One level_to_byte per level, then a table lookup per channel, not
    // lround and a division per channel.
    std::vector<std::uint8_t> byte(static_cast<size_t>(std::max(im.levels, 2)));
    for (size_t k = 0; k < byte.size(); ++k)
        byte[k] = level_to_byte(static_cast<int>(k), im.levels);
    // Uninitialised, in huge pages (huge_pages.h): value-initialised, its 4 KB
    // pages were ~960 of a 1280x1024 run's faults (~11 ms of CPU).
    const size_t n = im.level.size();
    const HugeArray<std::uint8_t> rgb = huge_array<std::uint8_t>(n);
    for (size_t k = 0; k < n; ++k) rgb[k] = byte[std::min<size_t>(im.level[k], byte.size() - 1)];
    std::vector<png_bytep> rows(static_cast<size_t>(im.height));
    for (int y = 0; y < im.height; ++y) rows[y] = rgb.get() + static_cast<size_t>(y) * im.width * 3;
    write_atomically(path, [&](const std::filesystem::path& tmp) {
        std::FILE* f = std::fopen(tmp.c_str(), "wb");
        if (!f) throw InputError(path.string(), "", "cannot open for writing");
        const bool written = write_png_rows(f, im.width, im.height, rows.data());
        if (std::fclose(f) != 0 || !written)
            throw InputError(path.string(), "", "cannot write PNG");
    });
}

} // namespace seamless
