// SPDX-License-Identifier: MIT
#include <seamless/base/error.h>
#include <seamless/mesh/io/mesh_formats.h>

#include <cctype>

namespace seamless {
namespace {

std::string lower_case(std::string_view s) {
    std::string r(s);
    for (char& c : r) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return r;
}

} // namespace

std::string mesh_extensions() {
    std::string list;
    for (const MeshFormatInfo& f : kMeshFormats) {
        if (!list.empty()) list += ' ';
        list += f.extension;
    }
    return list;
}

std::optional<MeshFormat> mesh_format_of(std::string_view extension) {
    const std::string ext = lower_case(extension);
    for (const MeshFormatInfo& f : kMeshFormats)
        if (f.extension == ext) return f.format;
    return std::nullopt;
}

bool is_mesh_extension(std::string_view extension) {
    return mesh_format_of(extension).has_value();
}

MeshFormat mesh_format(std::string_view extension, const std::string& file) {
    if (const auto format = mesh_format_of(extension)) return *format;
    throw InputError(file, "",
                     "unknown mesh extension '" + lower_case(extension) + "' (expected " +
                         mesh_extensions() + ")");
}

MeshFormat mesh_format(const std::filesystem::path& path) {
    return mesh_format(path.extension().string(), path.string());
}

} // namespace seamless
