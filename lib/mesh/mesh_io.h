// SPDX-License-Identifier: MIT
// Mesh files: .off .obj .ply .stl through OpenMesh (17 significant digits in
// text formats), .gltf .glb (glTF 2.0) through tinygltf. The format follows the
// file extension. Writers go through a temporary file and a rename, so a
// failure leaves no partial file.
#pragma once

#include <seamless/tessellate/triangle_mesh.h>

#include <filesystem>

namespace seamless {

// Throws InputError (naming the file) when the extension is unknown or writing fails.
void write_mesh(const std::filesystem::path& path, const TriangleMesh& mesh);

// Reads positions and triangles (polygons are fanned into triangles). glTF:
// every triangle primitive of every mesh, node transforms ignored. Vertices are
// kept as the file indexes them (no welding). Throws InputError on any defect.
TriangleMesh read_mesh(const std::filesystem::path& path);

// Extensions write_mesh and read_mesh know, e.g. {".off", ".obj", ...}.
bool is_mesh_extension(const std::string& ext);

} // namespace seamless
