// SPDX-License-Identifier: MIT
#include <seamless/render/image.h>

#include <seamless/base/atomic_file.h>
#include <seamless/base/error.h>

#include <stb/stb_image_write.h> // implementation in Debian's libstb

#include <cmath>

namespace seamless {

std::uint8_t level_to_byte(int k, int levels) {
    return static_cast<std::uint8_t>(std::lround(255.0 * k / (levels - 1)));
}

void write_png(const std::filesystem::path& path, const Image& im) {
    std::vector<std::uint8_t> rgb(im.level.size());
    for (size_t k = 0; k < rgb.size(); ++k) rgb[k] = level_to_byte(im.level[k], im.levels);
    write_atomically(path, [&](const std::filesystem::path& tmp) {
        if (!stbi_write_png(tmp.c_str(), im.width, im.height, 3, rgb.data(), im.width * 3))
            throw InputError(path.string(), "", "cannot write PNG");
    });
}

} // namespace seamless
