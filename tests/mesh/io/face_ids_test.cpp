// SPDX-License-Identifier: MIT
// Face ids (docs/formats.md, "Face ids"): placed_mesh gives every triangle
// its part and B-rep face, PLY and OBJ write them and read them back equal,
// and the placed copies are the part's mesh placed (mirrors turned).
#include "mesh/io/tessellated.h"
#include "test_util.h"

#include <seamless/mesh/io/mesh_io.h>
#include <seamless/mesh/io/placed_mesh.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <map>
#include <set>

using namespace seamless;

namespace {

using test::tessellated;

// Writes `mesh` as `name` and reads it back.
TriangleMesh round_trip(const TriangleMesh& mesh, const std::string& name) {
    const auto path = test::scratch_dir("face_ids") / name;
    write_mesh(path, mesh);
    return read_mesh(path);
}

// A glTF read back (g) gives every triangle the solid of its face in the
// mesh written (placed): `check` judges a glTF's solids apart as a PLY's.
void check_solids_by_face(const TriangleMesh& placed, const TriangleMesh& g) {
    REQUIRE(placed.triangle_solid.size() == placed.triangles.size());
    REQUIRE(g.triangle_solid.size() == g.triangles.size());
    std::map<int, int> solid_of_face;
    for (size_t t = 0; t < placed.triangles.size(); ++t)
        solid_of_face[placed.triangle_face[t]] = placed.triangle_solid[t];
    for (size_t t = 0; t < g.triangles.size(); ++t)
        CHECK(g.triangle_solid[t] == solid_of_face.at(g.triangle_face[t]));
}

void check_same_ids(const TriangleMesh& a, const TriangleMesh& b) {
    REQUIRE(b.triangles == a.triangles);
    REQUIRE(b.positions.size() == a.positions.size());
    for (size_t v = 0; v < a.positions.size(); ++v)
        CHECK(test::same_bytes(b.positions[v], a.positions[v]));
    CHECK(b.triangle_face == a.triangle_face);
    CHECK(b.triangle_part == a.triangle_part);
    CHECK(b.part_names == a.part_names);
}

// Triangles whose winding and corner normals agree (the geometric normal
// within 90 degrees of the corners' mean).
int agreeing(const TriangleMesh& m) {
    int n = 0;
    for (int t = 0; t < m.triangle_count(); ++t) {
        const auto& f = m.triangles[t];
        const Vec3 g =
            cross(m.positions[f[1]] - m.positions[f[0]], m.positions[f[2]] - m.positions[f[0]]);
        const auto& c = m.corner_normals[t];
        n += dot(g, c[0] + c[1] + c[2]) > 0;
    }
    return n;
}

} // namespace

TEST_CASE("placed_mesh: each instance a copy of its part's mesh, with part and face ids",
          "[mesh][io][face_ids]") {
    const Model m = test::small_assembly();
    const TriangleMesh mesh = tessellated(m);
    const TriangleMesh placed = placed_mesh(mesh, m);
    const Model flat = flatten_assembly(m);
    // Triangles per part in the part's mesh.
    const std::vector<int> face_on = face_of_surface(m);
    std::vector<int> part_triangles(m.assembly.parts.size(), 0);
    for (int s : mesh.triangle_surface) ++part_triangles[face_on[s]]; // face k is part k's
    int expected = 0;
    for (const AssemblyNode& n : m.assembly.nodes)
        if (n.part >= 0) expected += part_triangles[n.part];
    CHECK(placed.triangle_count() == expected);
    REQUIRE(placed.triangle_face.size() == placed.triangles.size());
    REQUIRE(placed.triangle_part.size() == placed.triangles.size());
    CHECK(placed.part_names == std::vector<std::string>{"plate", "tube"});
    const std::vector<int> sources = placed_face_sources(m);
    REQUIRE(sources.size() == flat.brep.faces.size());
    for (int t = 0; t < placed.triangle_count(); ++t) {
        const int f = placed.triangle_face[t];
        REQUIRE(f >= 0);
        REQUIRE(f < static_cast<int>(flat.brep.faces.size()));
        CHECK(placed.surface_names[placed.triangle_surface[t]] == flat.brep.faces[f].name);
        CHECK(placed.triangle_part[t] == (sources[f] == 0 ? 0 : 1));
    }
    // The mirrored tube keeps its triangles' windings agreeing with their normals.
    CHECK(agreeing(mesh) == mesh.triangle_count());
    CHECK(agreeing(placed) == placed.triangle_count());
}

TEST_CASE("Face ids round-trip through PLY and OBJ", "[mesh][io][face_ids]") {
    const Model m = test::small_assembly();
    const TriangleMesh placed = placed_mesh(tessellated(m), m);
    for (const char* name : {"a.ply", "a.obj"}) {
        INFO(name);
        check_same_ids(placed, round_trip(placed, name));
    }
    // A coloured part without a tree: one part named after its file.
    Model part = test::plate_with_hole();
    part.source = "dir/plate.step";
    part.assembly.colours = {{0.2, 0.2, 0.2, 1}};
    part.assembly.face_colours = {0};
    const TriangleMesh one = placed_mesh(tessellated(part), part);
    CHECK(one.part_names == std::vector<std::string>{"plate"});
    CHECK(one.triangle_face == std::vector<int>(one.triangles.size(), 0));
    for (const char* name : {"p.ply", "p.obj"}) {
        INFO(name);
        check_same_ids(one, round_trip(one, name));
    }
}

TEST_CASE("glTF face and solid extras read back as face and solid ids", "[mesh][io][face_ids]") {
    const Model m = test::small_assembly();
    const TriangleMesh placed = placed_mesh(tessellated(m), m);
    const TriangleMesh g = round_trip(placed, "a.glb");
    REQUIRE(g.triangle_face.size() == g.triangles.size());
    CHECK(g.triangle_part == std::vector<int>(g.triangles.size(), -1));
    // One glTF mesh per face here: its triangles' ids are the face's.
    for (size_t t = 0; t < g.triangles.size(); ++t)
        CHECK(g.surface_names[g.triangle_surface[t]] == placed.surface_names[g.triangle_face[t]]);
    std::vector<int> a = g.triangle_face, b = placed.triangle_face;
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    CHECK(a == b);
    check_solids_by_face(placed, g);
    // Without face ids none are read, nor when one primitive lacks them.
    TriangleMesh bare = placed;
    bare.triangle_face.clear();
    CHECK(round_trip(bare, "bare.glb").triangle_face.empty());
    const auto path = test::scratch_dir("face_ids_gltf") / "a.gltf";
    write_mesh(path, placed);
    std::ifstream in(path);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    REQUIRE(read_mesh(path).triangle_face.size() == placed.triangles.size());
    // A primitive without solid runs: face ids, no solid ids.
    text.replace(text.find("\"solids\""), 8, "\"solidz\"");
    test::write_file(path, text);
    CHECK(read_mesh(path).triangle_face.size() == placed.triangles.size());
    CHECK(read_mesh(path).triangle_solid.empty());
    text.replace(text.find("\"faces\""), 7, "\"fakes\"");
    test::write_file(path, text);
    CHECK(read_mesh(path).triangle_face.empty());
}

TEST_CASE("OBJ and PLY face ids: names, parts out of order, parts and faces of none",
          "[mesh][io][face_ids]") {
    TriangleMesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    m.triangles = {{0, 1, 2}, {1, 3, 2}, {0, 2, 3}, {0, 3, 1}};
    m.triangle_part = {2, 0, -1, 2};
    m.triangle_face = {5, 0, -1, 6};
    m.part_names = {"-", "no\nname", "nut bolt"};
    const TriangleMesh obj = round_trip(m, "odd.obj");
    CHECK(obj.triangle_part == m.triangle_part);
    CHECK(obj.triangle_face == m.triangle_face);
    CHECK(obj.part_names == std::vector<std::string>{"part_0", "no name", "nut bolt"});
    const TriangleMesh ply = round_trip(m, "odd.ply");
    CHECK(ply.triangle_part == m.triangle_part);
    CHECK(ply.triangle_face == m.triangle_face);
    CHECK(ply.part_names == std::vector<std::string>{"-", "no name", "nut bolt"});
    // Files without ids read without them; ids out of range are refused.
    TriangleMesh bare = m;
    bare.triangle_part.clear();
    bare.triangle_face.clear();
    for (const char* name : {"bare.obj", "bare.ply"}) {
        const TriangleMesh r = round_trip(bare, name);
        CHECK(r.triangle_face.empty());
        CHECK(r.triangle_part.empty());
    }
    const auto dir = test::scratch_dir("face_ids_bad");
    test::write_file(dir / "bad.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\n"
                                      "property double y\nproperty double z\nelement face 1\n"
                                      "property list uchar int vertex_indices\n"
                                      "property int face_id\nend_header\n"
                                      "0 0 0\n1 0 0\n0 1 0\n3 0 1 2 -2\n");
    CHECK_THROWS_AS(read_mesh(dir / "bad.ply"), InputError);
}

TEST_CASE("Face ids of the corpus's assembly and a coloured part round-trip",
          "[mesh][io][face_ids][heavy]") {
    for (const char* file : {"occt_as1-oc-214-mat.stp", "ksu_R_0603.step"}) {
        INFO(file);
        ModelLoadOptions keep;
        keep.keep_assembly = true;
        const Model m = load_model(test::shared_dir() / "models" / "cad-corpus" / file, keep);
        const TriangleMesh placed = placed_mesh(tessellated(m), m);
        const Model flat = flatten_assembly(m);
        for (int f : placed.triangle_face) {
            CHECK(f >= 0);
            CHECK(f < static_cast<int>(flat.brep.faces.size()));
        }
        for (const char* ext : {".ply", ".obj"}) {
            INFO(ext);
            check_same_ids(placed, round_trip(placed, std::string("corpus") + ext));
        }
        // glTF: every triangle's solid is its face's (as1: 18 solids).
        const TriangleMesh g = round_trip(placed, "corpus.glb");
        check_solids_by_face(placed, g);
        CHECK(std::set<int>(g.triangle_solid.begin(), g.triangle_solid.end()).size() ==
              std::set<int>(placed.triangle_solid.begin(), placed.triangle_solid.end()).size());
    }
}

TEST_CASE("placed_counts counts what placed_mesh holds, without placing", "[mesh][io][face_ids]") {
    const Model m = test::small_assembly();
    const TriangleMesh mesh = tessellated(m);
    const TriangleMesh placed = placed_mesh(mesh, m);
    const PlacedCounts counts = placed_counts(mesh, m);
    CHECK(counts.triangles == placed.triangle_count());
    CHECK(counts.vertices == placed.vertex_count());
    REQUIRE(counts.parts.size() == m.assembly.parts.size());
    long long per_part = 0;
    for (size_t p = 0; p < counts.parts.size(); ++p) {
        long long on_part = 0; // placed triangles of part p
        for (int tp : placed.triangle_part) on_part += tp == static_cast<int>(p);
        CHECK(on_part == counts.parts[p].instances * counts.parts[p].triangles);
        per_part += counts.parts[p].triangles;
    }
    CHECK(per_part == mesh.triangle_count()); // every triangle on a part's face
    CHECK(counts.parts[1].instances == 3);
    // Without a tree: the mesh's own counts.
    const Model part = test::plate_with_hole();
    const TriangleMesh one = tessellated(part);
    CHECK(placed_counts(one, part).triangles == one.triangle_count());
    CHECK(placed_counts(one, part).parts.empty());
    // Each triangle's face by its surface, as placed_mesh gives a model without a tree.
    CHECK(triangle_faces(one, part) == placed_mesh(one, part).triangle_face);
}
