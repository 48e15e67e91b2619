// SPDX-License-Identifier: MIT
// Mesh files: OFF, OBJ, PLY, STL (our readers and writers: every coordinate
// round-trips bit-identically, mesh_io.cpp says why not OpenMesh's) and glTF
// 2.0 through tinygltf. The format follows the file extension (kMeshFormats,
// mesh_formats.h). Writers go through a temporary file and a rename, so a
// failure leaves no partial file.
#pragma once

#include <seamless/base/triangle_mesh.h>
#include <seamless/mesh/io/gltf_io.h>
#include <seamless/mesh/io/mesh_formats.h>
#include <seamless/model/model.h>

#include <cstdint>
#include <filesystem>
#include <string>

namespace seamless {

// Largest mesh file read (and largest external glTF buffer): 2 GiB.
inline constexpr std::uintmax_t kMaxMeshFileBytes = std::uintmax_t(1) << 31;

// Throws InputError (naming the file) when the extension is unknown or
// writing fails. OBJ and PLY write the mesh's face ids when it has them
// (triangle_face and triangle_part: placed_mesh.h); `gltf` applies to glTF.
void write_mesh(const std::filesystem::path& path, const TriangleMesh& mesh,
                const GltfWriteOptions& gltf = {});

// A CAD assembly's mesh (gltf_io.h, write_gltf_assembly) as .gltf or .glb,
// atomically; other formats are refused (they flatten: write_mesh).
void write_mesh_assembly(const std::filesystem::path& path, const TriangleMesh& mesh,
                         const Model& model, const GltfWriteOptions& gltf = {});

// Reads positions and triangles (polygons are fanned into triangles), and
// the face ids of OBJ and PLY files that carry them. glTF:
// every triangle primitive of every mesh, node transforms ignored. Vertices are
// kept as the file indexes them (no welding). Throws InputError on any defect.
// A file that is not a regular file, exceeds 2 GiB or holds no triangle is an
// error too (docs/formats.md, Limits).
TriangleMesh read_mesh(const std::filesystem::path& path);

// The same from the bytes of a file: `format` is its extension (".off" ...),
// `file` names it in messages, `base_dir` is where a .gltf's external buffers
// are looked up.
TriangleMesh parse_mesh(const std::string& bytes, const std::string& format,
                        const std::string& file, const std::filesystem::path& base_dir = {});

} // namespace seamless
