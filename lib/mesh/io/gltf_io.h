// SPDX-License-Identifier: MIT
// glTF 2.0 (.gltf with an embedded base64 buffer, .glb) through tinygltf
// (gltf_write.cpp, gltf_read.cpp); used by mesh_io.cpp, which picks the format
// from the extension.
#pragma once

#include <seamless/base/triangle_mesh.h>
#include <seamless/model/model.h>

#include <filesystem>
#include <string>

namespace seamless {

struct GltfWriteOptions {
    // Metres per model unit (glTF's unit is the metre): positions and
    // placements' translations are multiplied by it; 1 leaves them as they are.
    double scale = 1;
    // write_gltf_assembly: every instance placed (placed_mesh.h) in one mesh
    // and node, one primitive per colour, instead of the tree.
    bool merge = false;
};

// One glTF mesh (and node) per source surface, named after it, with one indexed
// triangle primitive: POSITION (float32, min/max), NORMAL (unit float32, from
// corner_normals) and TEXCOORD_0 (float32, from corner_uvs) when present. A vertex
// is split where its corners differ in normal or uv. With face ids
// (triangle_face) each primitive's extras hold them (docs/formats.md, "Face
// ids"). Writes `path` directly (the caller provides atomicity); throws
// InputError naming `name` on failure.
void write_gltf(const std::filesystem::path& path, const TriangleMesh& mesh, bool binary,
                const std::string& name, const GltfWriteOptions& options = {});

// A CAD assembly as glTF: `mesh` is the tessellation of `model`, a model
// that keeps its assembly (each part once, in its own coordinates, its faces
// on surfaces of their own: triangle_surface names the face). One glTF mesh
// per part, one primitive per colour of its faces, shared by every node
// that places the part; one node per assembly node, named as it and placed
// by its matrix; one material per colour (PBR metallic-roughness: the
// colour, linearised, as baseColorFactor, its alpha blended); each
// primitive's extras give its triangles' faces (indices into model's faces);
// the scene's extras the layers (docs/formats.md, "Layers"). With
// options.merge, one mesh and node instead, its face ids those of
// flatten_assembly(model). Throws InputError naming `name` on failure. A
// B-rep model with colours or layers and no tree is written as one part
// placed once.
void write_gltf_assembly(const std::filesystem::path& path, const TriangleMesh& mesh,
                         const Model& model, bool binary, const std::string& name,
                         const GltfWriteOptions& options = {});

// Every triangle primitive (modes 4, 5, 6) of every mesh, as indexed, no welding;
// triangle_surface is the glTF mesh index, surface_names the mesh names; corner
// normals and uvs are read when every primitive has them, face ids
// (triangle_face; triangle_part -1) when every primitive's extras give them.
// Images are not decoded; external buffers are read as input files are
// (regular files within the mesh size limit). Limits: JSON nesting depth 64,
// at most one triangle per byte of the file and its buffers (docs/formats.md).
TriangleMesh read_gltf(const std::filesystem::path& path);
// The same from a file's bytes; `file` names it in messages, external buffers
// are looked up in `base_dir`.
TriangleMesh parse_gltf(const std::string& bytes, bool binary, const std::string& file,
                        const std::filesystem::path& base_dir);

} // namespace seamless
