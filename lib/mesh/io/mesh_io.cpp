// SPDX-License-Identifier: MIT
// Mesh files by format (mesh_formats.h): OFF, OBJ, PLY and STL (one file per
// format, mesh_text.h), glTF (gltf_io.h).
//
// Why not OpenMesh IO for these: OpenMesh 9's readers and writers pass every
// point through Vec3f (BaseImporter::add_vertex(Vec3f), BaseExporter::point), so
// even with a precision of 17 digits a text file holds float values and reading
// 0.1 yields 0.10000000149011612. Its OBJ reader also drops faces with a repeated
// vertex and its STL reader merges equal vertices. The code here writes every
// coordinate as the shortest decimal that reads back to the same double
// (std::to_chars, at most 17 significant digits) and parses with std::from_chars
// (correctly rounded), so text files round-trip bit-identically, and reads every
// face exactly as the file indexes it.
#include <seamless/base/check.h>
#include <seamless/base/error.h>
#include <seamless/base/files/atomic_file.h>
#include <seamless/base/files/input_file.h>
#include <seamless/mesh/io/gltf_io.h>
#include <seamless/mesh/io/mesh_io.h>
#include <seamless/mesh/io/mesh_text.h>

#include <fstream>
#include <string>

namespace seamless {
namespace {

namespace fs = std::filesystem;

// Shared checks of what every reader produced.
void validate(const TriangleMesh& mesh, const std::string& file) {
    for (size_t i = 0; i < mesh.positions.size(); ++i)
        if (!is_finite(mesh.positions[i]))
            throw InputError(file, "vertex " + std::to_string(i), "non-finite coordinate");
    const int n = mesh.vertex_count();
    for (size_t t = 0; t < mesh.triangles.size(); ++t)
        for (int v : mesh.triangles[t])
            if (v < 0 || v >= n)
                throw InputError(file, "triangle " + std::to_string(t),
                                 "vertex index " + std::to_string(v) + " out of range [0, " +
                                     std::to_string(n) + ")");
}

bool is_gltf(MeshFormat format) {
    return format == MeshFormat::gltf || format == MeshFormat::glb;
}

// The file's text in one of the text formats.
std::string format_text(MeshFormat format, const TriangleMesh& mesh) {
    switch (format) {
    case MeshFormat::off:
        return mesh_text::format_off(mesh);
    case MeshFormat::obj:
        return mesh_text::format_obj(mesh);
    case MeshFormat::ply:
        return mesh_text::format_ply(mesh);
    case MeshFormat::stl:
        return mesh_text::format_stl(mesh);
    case MeshFormat::gltf:
    case MeshFormat::glb:
        break;
    }
    SEAMLESS_CHECK(false, "glTF is written by write_gltf, not as text");
}

TriangleMesh read_format(MeshFormat format, const std::string& bytes, const std::string& file,
                         const fs::path& base_dir) {
    switch (format) {
    case MeshFormat::gltf:
        return parse_gltf(bytes, false, file, base_dir);
    case MeshFormat::glb:
        return parse_gltf(bytes, true, file, base_dir);
    case MeshFormat::off:
        return mesh_text::read_off(bytes, file);
    case MeshFormat::obj:
        return mesh_text::read_obj(bytes, file);
    case MeshFormat::ply:
        return mesh_text::read_ply(bytes, file);
    case MeshFormat::stl:
        return mesh_text::read_stl(bytes, file);
    }
    SEAMLESS_CHECK(false, "a mesh format without a reader");
}

// The mesh of a file's bytes in `format`, checked.
TriangleMesh parse_as(MeshFormat format, const std::string& bytes, const std::string& file,
                      const fs::path& base_dir) {
    TriangleMesh mesh =
        naming_file_on_oom(file, [&] { return read_format(format, bytes, file, base_dir); });
    validate(mesh, file);
    // A file with nothing to check is never a clean mesh.
    if (mesh.triangles.empty()) throw InputError(file, "", "holds no triangles");
    return mesh;
}

} // namespace

void write_mesh(const std::filesystem::path& path, const TriangleMesh& mesh,
                const GltfWriteOptions& gltf) {
    const MeshFormat format = mesh_format(path);
    const std::string file = path.string();
    validate(mesh, file);
    if (is_gltf(format)) {
        write_atomically(path, [&](const fs::path& tmp) {
            write_gltf(tmp, mesh, format == MeshFormat::glb, file, gltf);
        });
        return;
    }
    const std::string text = format_text(format, mesh);
    write_atomically(path, [&](const fs::path& tmp) {
        std::ofstream out(tmp, std::ios::binary);
        if (!out) throw InputError(file, "", "cannot open for writing");
        out.write(text.data(), static_cast<std::streamsize>(text.size()));
        out.close();
        if (!out) throw InputError(file, "", "write failed");
    });
}

void write_mesh_assembly(const std::filesystem::path& path, const TriangleMesh& mesh,
                         const Model& model, const GltfWriteOptions& gltf) {
    const MeshFormat format = mesh_format(path);
    const std::string file = path.string();
    if (!is_gltf(format))
        throw InputError(file, "", "an assembly's tree is written as glTF (.gltf, .glb) only");
    validate(mesh, file);
    write_atomically(path, [&](const fs::path& tmp) {
        write_gltf_assembly(tmp, mesh, model, format == MeshFormat::glb, file, gltf);
    });
}

TriangleMesh parse_mesh(const std::string& bytes, const std::string& format,
                        const std::string& file, const std::filesystem::path& base_dir) {
    return parse_as(mesh_format(format, file), bytes, file, base_dir);
}

TriangleMesh read_mesh(const std::filesystem::path& path) {
    const MeshFormat format = mesh_format(path);
    const std::string bytes = read_input_file(path, kMaxMeshFileBytes, "mesh");
    return parse_as(format, bytes, path.string(), path.parent_path());
}

} // namespace seamless
