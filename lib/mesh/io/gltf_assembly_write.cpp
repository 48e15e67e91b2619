// SPDX-License-Identifier: MIT
// A CAD assembly as glTF (gltf_io.h, write_gltf_assembly): the tree, one
// mesh per part shared by its instances, or (--merge) every instance placed
// in one mesh; one material per colour; the layers as the scene's extras.
#include <seamless/base/error.h>
#include <seamless/mesh/io/gltf_io.h>
#include <seamless/mesh/io/gltf_primitives.h>
#include <seamless/mesh/io/mesh_text.h>
#include <seamless/mesh/io/placed_mesh.h>

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>

namespace seamless {
namespace {

// sRGB (how CAD files write colours) to glTF's linear baseColorFactor.
double linear(double c) {
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

void add_material(tinygltf::Model& model, const Rgba& c, int k) {
    tinygltf::Material m;
    m.name = "colour-" + std::to_string(k);
    m.pbrMetallicRoughness.baseColorFactor = {linear(c.r), linear(c.g), linear(c.b), c.a};
    m.pbrMetallicRoughness.metallicFactor = 0; // glTF's default, 1, would be metal
    m.pbrMetallicRoughness.roughnessFactor = 0.5;
    if (c.a < 1) m.alphaMode = "BLEND";
    model.materials.push_back(std::move(m));
}

// The node's placement as glTF's column-major 4x4 matrix; none for the identity.
// Its translation times `scale` (the positions are scaled, the rotation stays).
std::vector<double> node_matrix(const AffineMap& p, double scale) {
    const AffineMap id;
    if (std::equal(p.m, p.m + 12, id.m)) return {};
    std::vector<double> m(16, 0.0);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) m[4 * c + r] = p.m[4 * r + c] * (c == 3 ? scale : 1.0);
    m[15] = 1;
    return m;
}

// The triangles of a part, grouped by their face's colour (-1: none).
using ColourGroups = std::map<int, std::vector<int>>;

// Per part, its triangles grouped by colour; face_of[t]: triangle t's face
// in the model.
std::vector<ColourGroups> part_triangles(const TriangleMesh& mesh, const Model& model,
                                         const std::string& name, std::vector<int>& face_of) {
    const size_t nf = mesh.triangles.size();
    if (mesh.triangle_surface.size() != nf)
        throw InputError(name, "", "the mesh does not say which face each triangle is on");
    const std::vector<int> face_on = face_of_surface(model);
    const std::vector<int> part_of = face_parts(model.assembly, model.brep.faces.size());
    const std::vector<int> colours = face_colours(model);
    std::vector<ColourGroups> out(model.assembly.parts.size());
    face_of.assign(nf, -1);
    for (size_t t = 0; t < nf; ++t) {
        const int s = mesh.triangle_surface[t];
        const int f = s >= 0 && s < static_cast<int>(face_on.size()) ? face_on[s] : -1;
        if (f < 0 || part_of[f] < 0)
            throw InputError(name, "", "triangle " + std::to_string(t) + " is on no part's face");
        face_of[t] = f;
        out[part_of[f]][colours[f]].push_back(static_cast<int>(t));
    }
    return out;
}

// A model with colours or layers but no tree as one part placed once.
Model one_part(const Model& m, const std::string& name) {
    Model one = m;
    AssemblyPart part;
    part.name = std::filesystem::path(m.source.empty() ? name : m.source).stem().string();
    part.face_count = static_cast<int>(m.brep.faces.size());
    part.shell_count = static_cast<int>(m.brep.shells.size());
    part.solid_count = static_cast<int>(m.brep.solids.size());
    one.assembly.parts = {part};
    one.assembly.nodes = {{part.name, -1, AffineMap{}, 0}};
    return one;
}

// The model's materials, one per colour.
tinygltf::Model coloured_model(const Assembly& a) {
    tinygltf::Model model = new_gltf_model();
    for (size_t k = 0; k < a.colours.size(); ++k) add_material(model, a.colours[k], int(k));
    return model;
}

// A glTF mesh named `name` of one primitive per colour group, with face
// and solid extras.
tinygltf::Mesh grouped_mesh(tinygltf::Model& model, const TriangleMesh& mesh,
                            const ColourGroups& groups, const std::vector<int>& face_of,
                            const std::vector<int>& solid_of, const std::string& name,
                            double scale) {
    tinygltf::Mesh gmesh;
    gmesh.name = name;
    for (const auto& [colour, tris] : groups) {
        tinygltf::Primitive prim = add_triangles(model, mesh, tris, CornerData::of(mesh), scale);
        prim.material = colour;
        add_face_extras(prim, tris, face_of, solid_of);
        gmesh.primitives.push_back(std::move(prim));
    }
    return gmesh;
}

tinygltf::Value int_array(const std::vector<int>& v) {
    tinygltf::Value::Array a;
    for (int x : v) a.emplace_back(x);
    return tinygltf::Value(std::move(a));
}

// The layers as the scene's extras (docs/formats.md, "Layers"): per layer
// its name, visibility, the meshes of its parts (`meshes`) and the face ids
// (as the primitives' extras give them) of the rest (`faces`; each absent
// when empty: tinygltf writes an empty array as null). Nothing without layers.
void add_layer_extras(tinygltf::Scene& scene, const std::vector<AssemblyLayer>& layers,
                      const std::function<std::vector<int>(const AssemblyLayer&)>& meshes_of,
                      const std::function<std::vector<int>(const AssemblyLayer&)>& faces_of) {
    if (layers.empty()) return;
    tinygltf::Value::Array table;
    for (const AssemblyLayer& l : layers) {
        tinygltf::Value::Object layer;
        layer["name"] = tinygltf::Value(l.name);
        layer["visible"] = tinygltf::Value(l.visible);
        if (const std::vector<int> meshes = meshes_of(l); !meshes.empty())
            layer["meshes"] = int_array(meshes);
        if (const std::vector<int> faces = faces_of(l); !faces.empty())
            layer["faces"] = int_array(faces);
        table.emplace_back(std::move(layer));
    }
    tinygltf::Value::Object extras;
    extras["layers"] = tinygltf::Value(std::move(table));
    scene.extras = tinygltf::Value(std::move(extras));
}

void write_tree(const std::filesystem::path& path, const TriangleMesh& mesh, const Model& m,
                bool binary, const std::string& name, double scale) {
    const Assembly& a = m.assembly;
    tinygltf::Model model = coloured_model(a);
    std::vector<int> face_of;
    const auto parts = part_triangles(mesh, m, name, face_of);
    // Solids of the model with its tree kept, as the faces.
    const std::vector<int> solid_of_face = face_solids(m.brep);
    std::vector<int> solid_of(face_of.size());
    for (size_t t = 0; t < face_of.size(); ++t) solid_of[t] = solid_of_face[face_of[t]];
    // One mesh per part with triangles: glTF forbids a mesh without
    // primitives, so a part without faces has none (mesh_of -1).
    std::vector<int> mesh_of(parts.size(), -1);
    for (size_t p = 0; p < parts.size(); ++p) {
        if (parts[p].empty()) continue;
        mesh_of[p] = static_cast<int>(model.meshes.size());
        model.meshes.push_back(
            grouped_mesh(model, mesh, parts[p], face_of, solid_of, a.parts[p].name, scale));
    }
    tinygltf::Scene scene;
    for (size_t k = 0; k < a.nodes.size(); ++k) {
        const AssemblyNode& n = a.nodes[k];
        tinygltf::Node node;
        node.name = n.name;
        node.matrix = node_matrix(n.placement, scale);
        if (n.part >= 0) node.mesh = mesh_of[n.part];
        model.nodes.push_back(std::move(node));
        if (n.parent < 0)
            scene.nodes.push_back(static_cast<int>(k));
        else
            model.nodes[n.parent].children.push_back(static_cast<int>(k));
    }
    add_layer_extras(
        scene, a.layers,
        [&](const AssemblyLayer& l) {
            std::vector<int> meshes;
            for (int p : l.parts)
                if (mesh_of[p] >= 0) meshes.push_back(mesh_of[p]);
            return meshes;
        },
        [&](const AssemblyLayer& l) { return layer_faces(m, l, false); });
    model.scenes.push_back(scene);
    finish_and_write(model, path, binary, name);
}

// --merge: every instance placed (placed_mesh) in one mesh and node, one
// primitive per colour; the face ids are those of the placed model.
void write_merged(const std::filesystem::path& path, const TriangleMesh& mesh, const Model& m,
                  bool binary, const std::string& name, double scale) {
    const TriangleMesh placed = placed_mesh(mesh, m);
    if (placed.triangle_face.size() != placed.triangles.size())
        throw InputError(name, "", "the mesh does not say which face each triangle is on");
    const std::vector<int> sources = placed_face_sources(m), colours = face_colours(m);
    ColourGroups groups;
    for (size_t t = 0; t < placed.triangles.size(); ++t) {
        const int f = placed.triangle_face[t];
        groups[f >= 0 ? colours[sources[f]] : -1].push_back(static_cast<int>(t));
    }
    tinygltf::Model model = coloured_model(m.assembly);
    const std::string stem =
        std::filesystem::path(m.source.empty() ? name : m.source).stem().string();
    const std::vector<int> none;
    model.meshes.push_back(
        grouped_mesh(model, placed, groups, placed.triangle_face,
                     mesh_text::has_solid_ids(placed) ? placed.triangle_solid : none, stem, scale));
    tinygltf::Node node;
    node.name = stem;
    node.mesh = 0;
    model.nodes.push_back(std::move(node));
    tinygltf::Scene scene;
    scene.nodes.push_back(0);
    // A layer's faces, placed: every copy of each face it covers.
    add_layer_extras(
        scene, m.assembly.layers, [](const AssemblyLayer&) { return std::vector<int>(); },
        [&](const AssemblyLayer& l) {
            std::vector<char> in(m.brep.faces.size(), 0);
            for (int f : layer_faces(m, l, true)) in[f] = 1;
            std::vector<int> faces;
            for (size_t f = 0; f < sources.size(); ++f)
                if (in[sources[f]]) faces.push_back(static_cast<int>(f));
            return faces;
        });
    model.scenes.push_back(scene);
    finish_and_write(model, path, binary, name);
}

} // namespace

void write_gltf_assembly(const std::filesystem::path& path, const TriangleMesh& mesh,
                         const Model& m, bool binary, const std::string& name,
                         const GltfWriteOptions& options) {
    const auto write = options.merge ? write_merged : write_tree;
    if (m.assembly.has_tree())
        write(path, mesh, m, binary, name, options.scale);
    else
        write(path, mesh, one_part(m, name), binary, name, options.scale);
}

} // namespace seamless
