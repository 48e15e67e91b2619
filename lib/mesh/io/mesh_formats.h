// SPDX-License-Identifier: MIT
// The mesh file formats, one table: what write_mesh and read_mesh dispatch on
// (mesh_io.h), what the CLI's help texts and output checks list.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace seamless {

enum class MeshFormat { off, obj, ply, stl, gltf, glb };

struct MeshFormatInfo {
    MeshFormat format;
    std::string_view extension; // lower case, with its dot
    std::string_view name;
};

// Every mesh format, in the order help texts and messages list them.
inline constexpr std::array<MeshFormatInfo, 6> kMeshFormats{{
    {MeshFormat::off, ".off", "OFF"},
    {MeshFormat::obj, ".obj", "Wavefront OBJ"},
    {MeshFormat::ply, ".ply", "PLY"},
    {MeshFormat::stl, ".stl", "STL"},
    {MeshFormat::gltf, ".gltf", "glTF 2.0 (JSON, embedded or external buffers)"},
    {MeshFormat::glb, ".glb", "glTF 2.0 binary"},
}};

// ".off .obj .ply .stl .gltf .glb": the extensions of kMeshFormats, one space apart.
std::string mesh_extensions();

// The format whose extension is `extension` in any case (".STL"), or nullopt.
std::optional<MeshFormat> mesh_format_of(std::string_view extension);

// Whether `extension` (any case) is a mesh format's.
bool is_mesh_extension(std::string_view extension);

// The format of `extension`; throws InputError naming `file` for any other:
// "unknown mesh extension '.x' (expected .off .obj ...)".
MeshFormat mesh_format(std::string_view extension, const std::string& file);

// The format of `path`'s extension; throws InputError naming the path for any other.
MeshFormat mesh_format(const std::filesystem::path& path);

} // namespace seamless
