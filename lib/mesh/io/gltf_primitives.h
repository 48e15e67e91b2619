// SPDX-License-Identifier: MIT
// What the glTF writers share (gltf_write.cpp: one node per surface;
// gltf_assembly_write.cpp: the tree and --merge): primitives built from a
// mesh's triangles, their face-id extras, and the file written. Internal to
// lib/mesh/io.
#pragma once

#include <seamless/base/triangle_mesh.h>

#include <filesystem>
#include <string>
#include <vector>

namespace tinygltf { // tiny_gltf.h stays in the .cpp files
class Model;
struct Primitive;
} // namespace tinygltf

namespace seamless {

// What a mesh holds per triangle corner, written when it holds it for every triangle.
struct CornerData {
    bool normals = false, uvs = false;
    static CornerData of(const TriangleMesh& mesh) {
        const size_t nf = mesh.triangles.size();
        return {mesh.corner_normals.size() == nf && nf > 0, mesh.corner_uvs.size() == nf && nf > 0};
    }
};

// A new glTF model with one (empty) buffer.
tinygltf::Model new_gltf_model();

// An indexed triangle primitive of triangles `tris` of `mesh`, its positions
// times `scale`, its accessors and views appended to the model's buffer; a
// vertex is split where its corners differ in normal or uv.
tinygltf::Primitive add_triangles(tinygltf::Model& model, const TriangleMesh& mesh,
                                  const std::vector<int>& tris, CornerData has, double scale);

// The primitive's face and solid ids as its extras (docs/formats.md, "Face
// ids"): {"faces": [[face, first, count], ...], "solids": [[solid, first,
// count], ...]}, one entry per run of consecutive triangles of `tris` on one
// face (face_of[t], -1 for none) or in one solid (solid_of[t]); a member
// only when its ids are not empty.
void add_face_extras(tinygltf::Primitive& prim, const std::vector<int>& tris,
                     const std::vector<int>& face_of, const std::vector<int>& solid_of);

// Writes the model (scene 0 the default); throws InputError naming `name`.
void finish_and_write(tinygltf::Model& model, const std::filesystem::path& path, bool binary,
                      const std::string& name);

} // namespace seamless
