// SPDX-License-Identifier: MIT
// Mesh files by extension: OFF, OBJ, PLY and STL (one file per format,
// mesh_text.h), glTF (gltf_io.h).
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
#include <seamless/base/error.h>
#include <seamless/base/files/atomic_file.h>
#include <seamless/base/files/input_file.h>
#include <seamless/mesh/io/gltf_io.h>
#include <seamless/mesh/io/mesh_io.h>
#include <seamless/mesh/io/mesh_text.h>

#include <cctype>
#include <fstream>
#include <string>

namespace seamless {
namespace {

namespace fs = std::filesystem;

std::string lower_extension(const fs::path& path) {
    std::string ext = path.extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

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

} // namespace

bool is_mesh_extension(const std::string& ext) {
    std::string e = ext;
    for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return e == ".off" || e == ".obj" || e == ".ply" || e == ".stl" || e == ".gltf" || e == ".glb";
}

void write_mesh(const std::filesystem::path& path, const TriangleMesh& mesh) {
    const std::string ext = lower_extension(path);
    const std::string file = path.string();
    if (!is_mesh_extension(ext))
        throw InputError(file, "",
                         "unknown mesh extension '" + ext +
                             "' (expected .off .obj .ply .stl .gltf .glb)");
    validate(mesh, file);
    if (ext == ".gltf" || ext == ".glb") {
        write_atomically(path,
                         [&](const fs::path& tmp) { write_gltf(tmp, mesh, ext == ".glb", file); });
        return;
    }
    const std::string text = ext == ".off"   ? mesh_text::format_off(mesh)
                             : ext == ".obj" ? mesh_text::format_obj(mesh)
                             : ext == ".ply" ? mesh_text::format_ply(mesh)
                                             : mesh_text::format_stl(mesh);
    write_atomically(path, [&](const fs::path& tmp) {
        std::ofstream out(tmp, std::ios::binary);
        if (!out) throw InputError(file, "", "cannot open for writing");
        out.write(text.data(), static_cast<std::streamsize>(text.size()));
        out.close();
        if (!out) throw InputError(file, "", "write failed");
    });
}

TriangleMesh parse_mesh(const std::string& bytes, const std::string& format,
                        const std::string& file, const std::filesystem::path& base_dir) {
    std::string ext = format;
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (!is_mesh_extension(ext))
        throw InputError(file, "",
                         "unknown mesh extension '" + ext +
                             "' (expected .off .obj .ply .stl .gltf .glb)");
    TriangleMesh mesh = naming_file_on_oom(file, [&] {
        return ext == ".gltf"  ? parse_gltf(bytes, false, file, base_dir)
               : ext == ".glb" ? parse_gltf(bytes, true, file, base_dir)
               : ext == ".off" ? mesh_text::read_off(bytes, file)
               : ext == ".obj" ? mesh_text::read_obj(bytes, file)
               : ext == ".ply" ? mesh_text::read_ply(bytes, file)
                               : mesh_text::read_stl(bytes, file);
    });
    validate(mesh, file);
    // A file with nothing to check is never a clean mesh.
    if (mesh.triangles.empty()) throw InputError(file, "", "holds no triangles");
    return mesh;
}

TriangleMesh read_mesh(const std::filesystem::path& path) {
    const std::string ext = lower_extension(path);
    const std::string file = path.string();
    if (!is_mesh_extension(ext))
        throw InputError(file, "",
                         "unknown mesh extension '" + ext +
                             "' (expected .off .obj .ply .stl .gltf .glb)");
    const std::string bytes = read_input_file(path, kMaxMeshFileBytes, "mesh");
    return parse_mesh(bytes, ext, file, path.parent_path());
}

} // namespace seamless
