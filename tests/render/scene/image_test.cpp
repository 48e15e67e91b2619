// SPDX-License-Identifier: MIT
// Image (image.h): a filled image starts at level 0, background; an unfilled
// one is made whole by clearing parts that tile it (render_intracy's parts),
// and clear() writes only its rectangle. write_png: the file holds the
// levels as bytes.
#include "test_util.h"

#include <seamless/base/error.h>
#include <seamless/render/scene/image.h>

#include <catch2/catch.hpp>
#include <stb/stb_image.h> // implementation in Debian's libstb

#include <algorithm>
#include <filesystem>
#include <string>

using namespace seamless;

namespace {

bool all_clear(const Image& im) {
    return std::all_of(im.level.begin(), im.level.end(), [](auto v) { return v == 0; }) &&
           std::all_of(im.surface.begin(), im.surface.end(), [](auto v) { return v == 0; });
}

} // namespace

TEST_CASE("Image: filled at level 0; unfilled made whole by clearing tiles", "[image]") {
    const Image filled(37, 23, 16);
    REQUIRE(filled.level.size() == 37u * 23 * 3);
    REQUIRE(filled.surface.size() == 37u * 23);
    CHECK(all_clear(filled));

    // Tiles as render_intracy cuts them: 8 x 8 parts of uneven sizes.
    Image im(37, 23, 16, Image::Unfilled{});
    REQUIRE(im.level.size() == filled.level.size());
    std::fill(im.level.begin(), im.level.end(), std::uint16_t{7}); // stand-in for old contents
    std::fill(im.surface.begin(), im.surface.end(), std::uint8_t{1});
    const int px = 8, py = 8;
    for (int p = 0; p < px * py; ++p) {
        const int i = p % px, j = p / px;
        im.clear(i * 37 / px, j * 23 / py, (i + 1) * 37 / px - 1, (j + 1) * 23 / py - 1);
    }
    CHECK(all_clear(im));
    CHECK(im.level == filled.level);
    CHECK(im.surface == filled.surface);
}

TEST_CASE("Image: clear writes only its rectangle", "[image]") {
    Image im(10, 6, 16);
    std::fill(im.level.begin(), im.level.end(), std::uint16_t{5});
    std::fill(im.surface.begin(), im.surface.end(), std::uint8_t{1});
    im.clear(2, 1, 4, 3);
    int cleared = 0;
    for (int y = 0; y < 6; ++y)
        for (int x = 0; x < 10; ++x) {
            const bool inside = x >= 2 && x <= 4 && y >= 1 && y <= 3;
            for (int c = 0; c < 3; ++c) CHECK(im.at(x, y, c) == (inside ? 0 : 5));
            CHECK(im.surface_at(x, y) == (inside ? 0 : 1));
            cleared += inside;
        }
    CHECK(cleared == 9);
    im.clear(3, 0, 2, 5); // empty: x1 < x0
    CHECK(im.at(3, 0, 0) == 5);
}

TEST_CASE("Image: a render-size image (huge-page storage) tiled by clears, copied", "[image]") {
    // 1280 x 1024: 7.5 MB of levels, 1.25 MB of surface flags (huge_pages.h).
    Image im(1280, 1024, 256, Image::Unfilled{});
    for (int p = 0; p < 64; ++p) {
        const int i = p % 8, j = p / 8;
        im.clear(i * 160, j * 128, i * 160 + 159, j * 128 + 127);
    }
    CHECK(all_clear(im));
    im.at(1279, 1023, 2) = 255;
    const Image copy = im;
    CHECK(copy.level == im.level);
    CHECK(copy.at(1279, 1023, 2) == 255);
}

TEST_CASE("write_png: the file decodes to the image's levels as bytes", "[image]") {
    const auto dir = test::scratch_dir("image-png");
    for (int levels : {2, 16, 256}) {
        Image im(37, 23, levels);
        for (int y = 0; y < im.height; ++y)
            for (int x = 0; x < im.width; ++x)
                for (int c = 0; c < 3; ++c)
                    im.at(x, y, c) = static_cast<std::uint16_t>((x * 7 + y * 3 + c * 5) % levels);
        const auto path = dir / ("levels" + std::to_string(levels) + ".png");
        write_png(path, im);
        // Decoded by stb_image, not by the libpng that wrote it.
        int w = 0, h = 0, channels = 0;
        unsigned char* rgb = stbi_load(path.string().c_str(), &w, &h, &channels, 3);
        REQUIRE(rgb != nullptr);
        CHECK(w == im.width);
        CHECK(h == im.height);
        CHECK(channels == 3);
        int wrong = 0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                for (int c = 0; c < 3; ++c)
                    wrong += rgb[(y * w + x) * 3 + c] != level_to_byte(im.at(x, y, c), levels);
        stbi_image_free(rgb);
        CHECK(wrong == 0);
    }
}

TEST_CASE("write_png: an unwritable path is an InputError and leaves no file", "[image]") {
    const auto dir = test::scratch_dir("image-png-bad");
    const auto path = dir / "missing-folder" / "x.png";
    CHECK_THROWS_AS(write_png(path, Image(4, 3, 16)), InputError);
    CHECK_FALSE(std::filesystem::exists(path));
}
