// SPDX-License-Identifier: MIT
// An assembly written as glTF (write_mesh_assembly): the tree as nodes named
// as the assembly's, one mesh per part shared by its instances, one
// material per colour, read back with tinygltf.
#include "mesh/io/tessellated.h"
#include "test_util.h"

#include <seamless/base/error.h>
#include <seamless/mesh/io/mesh_io.h>
#include <seamless/mesh/io/placed_mesh.h>

#include <catch2/catch.hpp>

#include <tiny_gltf.h>

#include <cmath>
#include <set>

using namespace seamless;

namespace {

using test::tessellated;

tinygltf::Model written(const Model& m, const std::filesystem::path& path,
                        const GltfWriteOptions& options = {}) {
    write_mesh_assembly(path, tessellated(m), m, options);
    tinygltf::Model g;
    std::string err, warn;
    tinygltf::TinyGLTF io;
    REQUIRE(io.LoadBinaryFromFile(&g, &err, &warn, path.string()));
    return g;
}

// A primitive's triangles (its indices' count / 3).
int triangles(const tinygltf::Model& g, const tinygltf::Primitive& p) {
    return static_cast<int>(g.accessors[p.indices].count / 3);
}

// The primitive's face extras, [face, first, count] runs: they cover its
// triangles in order; returns the faces.
std::vector<int> face_runs(const tinygltf::Model& g, const tinygltf::Primitive& p) {
    REQUIRE(p.extras.Has("faces"));
    const tinygltf::Value& runs = p.extras.Get("faces");
    std::vector<int> faces;
    int next = 0;
    for (size_t k = 0; k < runs.ArrayLen(); ++k) {
        const tinygltf::Value& r = runs.Get(int(k));
        REQUIRE(r.ArrayLen() == 3);
        faces.push_back(r.Get(0).GetNumberAsInt());
        CHECK(r.Get(1).GetNumberAsInt() == next);
        next += r.Get(2).GetNumberAsInt();
    }
    CHECK(next == triangles(g, p));
    return faces;
}

} // namespace

TEST_CASE("An assembly as glTF: nodes as the tree, one mesh per part, materials per colour",
          "[mesh][io][assembly]") {
    const Model m = test::small_assembly();
    const Assembly& a = m.assembly;
    const tinygltf::Model g = written(m, test::scratch_dir("gltf_assembly") / "a.glb");
    REQUIRE(g.nodes.size() == a.nodes.size());
    CHECK(g.meshes.size() == a.parts.size());
    CHECK(g.materials.size() == a.colours.size());
    int instances = 0;
    for (size_t k = 0; k < a.nodes.size(); ++k) {
        CHECK(g.nodes[k].name == a.nodes[k].name);
        CHECK(g.nodes[k].mesh == a.nodes[k].part); // -1 for an assembly
        instances += g.nodes[k].mesh >= 0;
        if (a.nodes[k].parent >= 0) {
            const std::vector<int>& children = g.nodes[a.nodes[k].parent].children;
            CHECK(std::count(children.begin(), children.end(), int(k)) == 1);
        }
    }
    CHECK(instances == instance_count(a));
    REQUIRE(g.scenes.size() == 1);
    CHECK(g.scenes[0].nodes == std::vector<int>{0});
    // tube-1's translation in the matrix's last column.
    REQUIRE(g.nodes[2].matrix.size() == 16);
    CHECK(g.nodes[2].matrix[12] == 20);
    CHECK(g.nodes[1].matrix.empty()); // the identity is left out
    for (size_t p = 0; p < g.meshes.size(); ++p) CHECK(g.meshes[p].name == a.parts[p].name);
    // The plate is red (its part's colour), the tube's face green at alpha 0.5.
    REQUIRE(g.meshes[0].primitives.size() == 1);
    const auto& red = g.materials[g.meshes[0].primitives[0].material];
    CHECK(red.pbrMetallicRoughness.baseColorFactor == std::vector<double>{1, 0, 0, 1});
    const auto& green = g.materials[g.meshes[1].primitives[0].material];
    CHECK(green.pbrMetallicRoughness.baseColorFactor[3] == 0.5);
    CHECK(green.alphaMode == "BLEND");
    for (const auto& mesh : g.meshes)
        for (const auto& prim : mesh.primitives) CHECK(prim.attributes.count("NORMAL") == 1);
    // Face extras: the plate's primitive is on face 0, the tube's on face 1.
    CHECK(face_runs(g, g.meshes[0].primitives[0]) == std::vector<int>{0});
    CHECK(face_runs(g, g.meshes[1].primitives[0]) == std::vector<int>{1});
}

TEST_CASE("An assembly merged: one node and mesh, a primitive per colour, every instance placed",
          "[mesh][io][assembly]") {
    const Model m = test::small_assembly();
    GltfWriteOptions merge;
    merge.merge = true;
    const tinygltf::Model g = written(m, test::scratch_dir("gltf_merged") / "a.glb", merge);
    REQUIRE(g.nodes.size() == 1);
    REQUIRE(g.meshes.size() == 1);
    CHECK(g.nodes[0].mesh == 0);
    CHECK(g.nodes[0].matrix.empty());
    // Plate red, tube green: two colours, two primitives.
    std::set<int> materials;
    int total = 0;
    for (const auto& p : g.meshes[0].primitives) {
        materials.insert(p.material);
        total += triangles(g, p);
        for (int f : face_runs(g, p)) CHECK(f >= 0);
    }
    CHECK(g.meshes[0].primitives.size() == 2);
    CHECK(materials == std::set<int>{0, 1});
    CHECK(total == placed_mesh(tessellated(m), m).triangle_count());
}

TEST_CASE("glTF in metres: positions and translations scaled, nodes as before",
          "[mesh][io][assembly]") {
    const Model m = test::small_assembly();
    GltfWriteOptions metres;
    metres.scale = 0.001;
    const tinygltf::Model kept = written(m, test::scratch_dir("gltf_kept") / "a.glb");
    const tinygltf::Model g = written(m, test::scratch_dir("gltf_metres") / "a.glb", metres);
    REQUIRE(g.nodes.size() == kept.nodes.size());
    CHECK(g.nodes[2].matrix[12] == 20 * 0.001);
    CHECK(g.nodes[2].matrix[0] == kept.nodes[2].matrix[0]);
    for (size_t a = 0; a < g.accessors.size(); ++a)
        for (size_t k = 0; k < g.accessors[a].maxValues.size(); ++k) // POSITION's
            CHECK(g.accessors[a].maxValues[k] ==
                  Approx(0.001 * kept.accessors[a].maxValues[k]).margin(1e-9));
}

TEST_CASE("An assembly's tree is refused for formats without one", "[mesh][io][assembly]") {
    const Model m = test::small_assembly();
    TessellationOptions opt;
    opt.tolerance = 0.05;
    const TriangleMesh mesh = tessellate(m, opt).mesh;
    CHECK_THROWS_AS(write_mesh_assembly(test::scratch_dir("gltf_assembly_off") / "a.off", mesh, m),
                    InputError);
}

TEST_CASE("The corpus assemblies as glTF: every instance a node sharing its part's one mesh",
          "[mesh][io][assembly][heavy]") {
    for (const char* file : {"occt_as1-oc-214-mat.stp", "occt_trj3_s1-ct-214.stp"}) {
        INFO(file);
        ModelLoadOptions keep;
        keep.keep_assembly = true;
        const Model m = load_model(test::shared_dir() / "models" / "cad-corpus" / file, keep);
        const tinygltf::Model g = written(m, test::scratch_dir("gltf_corpus") / "a.glb");
        CHECK(g.meshes.size() == m.assembly.parts.size());
        CHECK(g.nodes.size() == m.assembly.nodes.size());
        int instances = 0;
        for (size_t k = 0; k < g.nodes.size(); ++k) {
            CHECK(g.nodes[k].name == m.assembly.nodes[k].name);
            CHECK(!g.nodes[k].name.empty());
            instances += g.nodes[k].mesh >= 0;
        }
        CHECK(instances == instance_count(m.assembly));
        // Merged: one node, a primitive per colour its placed faces use, the
        // triangles of every instance.
        GltfWriteOptions merge;
        merge.merge = true;
        const tinygltf::Model one = written(m, test::scratch_dir("gltf_corpus") / "m.glb", merge);
        CHECK(one.nodes.size() == 1);
        REQUIRE(one.meshes.size() == 1);
        const std::vector<int> colours = face_colours(m);
        std::set<int> used;
        for (int f : placed_face_sources(m)) used.insert(colours[f]);
        CHECK(one.meshes[0].primitives.size() == used.size());
        int total = 0;
        for (const auto& p : one.meshes[0].primitives) total += triangles(one, p);
        CHECK(total == placed_mesh(tessellated(m), m).triangle_count());
    }
}

TEST_CASE("A coloured model without a tree is one part placed once", "[mesh][io][assembly]") {
    Model m = test::plate_with_hole();
    m.assembly.colours = {{0.2, 0.2, 0.2, 1}};
    m.assembly.face_colours = {0};
    const tinygltf::Model g = written(m, test::scratch_dir("gltf_coloured") / "a.glb");
    REQUIRE(g.meshes.size() == 1);
    CHECK(g.nodes.size() == 1);
    REQUIRE(g.materials.size() == 1);
    CHECK(g.meshes[0].primitives[0].material == 0);
    const double dark = g.materials[0].pbrMetallicRoughness.baseColorFactor[0];
    CHECK(dark < 0.2); // sRGB 0.2 is linear 0.033
    CHECK(dark > 0);
}

namespace {

// The scene's layer table: per layer its name, meshes and faces.
struct GltfLayer {
    std::string name;
    bool visible = true;
    std::vector<int> meshes, faces;
};

std::vector<GltfLayer> scene_layers(const tinygltf::Model& g) {
    std::vector<GltfLayer> out;
    REQUIRE(g.scenes.size() == 1);
    const tinygltf::Value& extras = g.scenes[0].extras;
    if (!extras.Has("layers")) return out;
    const auto ints = [](const tinygltf::Value& v) {
        std::vector<int> x;
        for (size_t k = 0; k < v.ArrayLen(); ++k) x.push_back(v.Get(int(k)).GetNumberAsInt());
        return x;
    };
    const tinygltf::Value& table = extras.Get("layers");
    for (size_t k = 0; k < table.ArrayLen(); ++k) {
        const tinygltf::Value& l = table.Get(int(k));
        GltfLayer layer{l.Get("name").Get<std::string>(), l.Get("visible").Get<bool>(), {}, {}};
        if (l.Has("meshes")) layer.meshes = ints(l.Get("meshes"));
        if (l.Has("faces")) layer.faces = ints(l.Get("faces"));
        out.push_back(std::move(layer));
    }
    return out;
}

} // namespace

TEST_CASE("Layers as the scene's extras: a part's mesh, the faces of the rest, placed when merged",
          "[mesh][io][assembly]") {
    const Model m = test::small_assembly();
    const auto dir = test::scratch_dir("gltf_layers");
    const tinygltf::Model g = written(m, dir / "a.glb");
    const std::vector<GltfLayer> tree = scene_layers(g);
    REQUIRE(tree.size() == m.assembly.layers.size());
    for (size_t k = 0; k < tree.size(); ++k) {
        const AssemblyLayer& l = m.assembly.layers[k];
        CHECK(tree[k].name == l.name);
        CHECK(tree[k].visible == l.visible);
        CHECK(tree[k].meshes == l.parts); // every part here has triangles
        CHECK(tree[k].faces == layer_faces(m, l, false));
        // The faces name faces that some primitive's extras hold.
        for (int f : tree[k].faces) {
            bool held = false;
            for (const auto& mesh : g.meshes)
                for (const auto& p : mesh.primitives)
                    for (int face : face_runs(g, p)) held = held || face == f;
            CHECK(held);
        }
    }
    // Merged: the faces of the placed model, every copy.
    GltfWriteOptions merge;
    merge.merge = true;
    const std::vector<GltfLayer> merged = scene_layers(written(m, dir / "m.glb", merge));
    const Model flat = flatten_assembly(m);
    REQUIRE(merged.size() == flat.assembly.layers.size());
    for (size_t k = 0; k < merged.size(); ++k) {
        CHECK(merged[k].meshes.empty());
        CHECK(merged[k].faces == layer_faces(flat, flat.assembly.layers[k], true));
    }
    // Without layers, no scene extras.
    Model bare = m;
    bare.assembly.layers.clear();
    CHECK(written(bare, dir / "b.glb").scenes[0].extras.Type() == tinygltf::NULL_TYPE);
}

TEST_CASE("A part without faces has no glTF mesh (glTF forbids an empty one)",
          "[mesh][io][assembly]") {
    Model m = test::small_assembly();
    m.assembly.parts.insert(m.assembly.parts.begin() + 1, {"empty", 0, 0, 0, -1});
    for (AssemblyNode& n : m.assembly.nodes)
        if (n.part >= 1) ++n.part;
    m.assembly.nodes.push_back({"empty-1", 0, AffineMap{}, 1});
    m.assembly.layers.push_back({"all", true, {0, 1, 2}, {}, {}});
    validate_assembly(m, "a.json");
    const tinygltf::Model g = written(m, test::scratch_dir("gltf_empty_part") / "a.glb");
    REQUIRE(g.meshes.size() == 2); // plate and tube
    for (const auto& mesh : g.meshes) CHECK(!mesh.primitives.empty());
    CHECK(g.nodes.back().mesh == -1);
    CHECK(g.meshes[g.nodes[1].mesh].name == "plate");
    CHECK(g.meshes[g.nodes[2].mesh].name == "tube");
    CHECK(scene_layers(g).back().meshes == std::vector<int>{0, 1});
}
