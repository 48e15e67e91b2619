// SPDX-License-Identifier: MIT
// The check on files: meshes written by other programs (OpenMesh STL, a
// hand-built glb), and the CLI's exit statuses.
#include "check_shapes.h"
#include "test_util.h"

#include <seamless/mesh/check/check.h>
#include <seamless/mesh/io/mesh_io.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <cstdint>
#include <map>

using namespace seamless;
using namespace seamless::test;

TEST_CASE("check: reads an STL and a glb written by other programs") {
    const auto dir = test::scratch_dir("check_foreign");
    const TriangleMesh oct = octahedron({0.25, 0.5, 0.125}, 0.5); // float-exact coordinates
    {
        OpenMesh::TriMesh_ArrayKernelT<> om;
        std::vector<OpenMesh::VertexHandle> vh;
        for (Vec3 p : oct.positions)
            vh.push_back(om.add_vertex(OpenMesh::Vec3f(
                static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z))));
        for (auto t : oct.triangles) om.add_face(vh[t[0]], vh[t[1]], vh[t[2]]);
        om.request_face_normals();
        om.update_face_normals();
        OpenMesh::IO::Options opt(OpenMesh::IO::Options::Binary);
        REQUIRE(OpenMesh::IO::write_mesh(om, (dir / "om.stl").string(), opt));
    }
    const TriangleMesh stl = read_mesh(dir / "om.stl");
    CHECK(stl.vertex_count() == 24);
    const CheckReport rs = check_mesh(stl);
    CHECK(rs.welded_vertices == 18);
    CHECK(defects(rs) == Names{});
    CHECK(rs.closed);
    CHECK(rs.components[0].euler == 2);
    CHECK(rs.components[0].outward == true);

    // glb: upper and lower halves as two meshes, equator vertices repeated.
    {
        tinygltf::Model model;
        model.asset.version = "2.0";
        model.buffers.resize(1);
        auto& data = model.buffers[0].data;
        tinygltf::Scene scene;
        for (int half = 0; half < 2; ++half) {
            std::vector<float> pos;
            std::vector<uint16_t> idx;
            std::map<int, uint16_t> local;
            for (int t = 4 * half; t < 4 * half + 4; ++t)
                for (int v : oct.triangles[t]) {
                    auto [it, ins] = local.try_emplace(v, static_cast<uint16_t>(pos.size() / 3));
                    if (ins)
                        for (int k = 0; k < 3; ++k)
                            pos.push_back(static_cast<float>(oct.positions[v][k]));
                    idx.push_back(it->second);
                }
            while (idx.size() % 2) idx.push_back(0);
            auto add = [&](const void* p, size_t n, int target) {
                tinygltf::BufferView bv;
                bv.buffer = 0;
                bv.byteOffset = data.size();
                bv.byteLength = n;
                bv.target = target;
                data.insert(data.end(), static_cast<const unsigned char*>(p),
                            static_cast<const unsigned char*>(p) + n);
                model.bufferViews.push_back(bv);
                return static_cast<int>(model.bufferViews.size()) - 1;
            };
            tinygltf::Accessor pa;
            pa.bufferView = add(pos.data(), pos.size() * 4, 34962);
            pa.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
            pa.type = TINYGLTF_TYPE_VEC3;
            pa.count = pos.size() / 3;
            pa.minValues = {-1, -1, -1};
            pa.maxValues = {1, 1, 1};
            model.accessors.push_back(pa);
            tinygltf::Accessor ia;
            ia.bufferView = add(idx.data(), 12 * 2, 34963);
            ia.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
            ia.type = TINYGLTF_TYPE_SCALAR;
            ia.count = 12;
            model.accessors.push_back(ia);
            tinygltf::Primitive prim;
            prim.attributes["POSITION"] = static_cast<int>(model.accessors.size()) - 2;
            prim.indices = static_cast<int>(model.accessors.size()) - 1;
            prim.mode = TINYGLTF_MODE_TRIANGLES;
            tinygltf::Mesh gm;
            gm.primitives.push_back(prim);
            model.meshes.push_back(gm);
            tinygltf::Node node;
            node.mesh = half;
            model.nodes.push_back(node);
            scene.nodes.push_back(half);
        }
        model.scenes.push_back(scene);
        model.defaultScene = 0;
        tinygltf::TinyGLTF io;
        REQUIRE(
            io.WriteGltfSceneToFile(&model, (dir / "two.glb").string(), true, true, false, true));
    }
    const TriangleMesh glb = read_mesh(dir / "two.glb");
    CHECK(glb.vertex_count() == 10);
    CHECK(glb.triangle_count() == 8);
    const CheckReport rg = check_mesh(glb);
    CHECK(rg.welded_vertices == 4);
    CHECK(defects(rg) == Names{});
    CHECK(rg.closed);
    CHECK(*rg.components[0].volume == Approx(4.0 / 3.0 * 0.125));
    CheckOptions raw;
    raw.weld = false;
    const CheckReport rn = check_mesh(glb, raw);
    CHECK(defects(rn) == Names{"cracks"});
    CHECK(rn.widest_crack == 0);
}

TEST_CASE("check CLI: exit status 0, 1 and 2") {
    const auto dir = test::scratch_dir("check_cli");
    write_mesh(dir / "oct.off", octahedron());
    TriangleMesh open;
    add_piece(open, 0, 1, 2, 2);
    write_mesh(dir / "open.ply", open);
    TriangleMesh tj;
    add_piece(tj, 0, 0.5, 2, 2);
    add_piece(tj, 0.5, 1, 2, 4);
    write_mesh(dir / "tj.glb", tj);

    auto r = test::run_cli("check \"" + (dir / "oct.off").string() + "\" --closed");
    CHECK(r.status == 0);
    CHECK(r.out.find("Euler characteristic 2") != std::string::npos);
    r = test::run_cli("check \"" + (dir / "open.ply").string() + "\"");
    CHECK(r.status == 0);
    r = test::run_cli("check \"" + (dir / "open.ply").string() + "\" --closed");
    CHECK(r.status == 1);
    r = test::run_cli("check \"" + (dir / "tj.glb").string() + "\" --json");
    CHECK(r.status == 1);
    const auto j = nlohmann::json::parse(r.out);
    CHECK(j["t_junctions"]["count"] == 2);
    CHECK(j["t_junctions"]["listed"].size() == 2);
    CHECK(j["t_junctions"]["listed"][0]["location"].size() == 3);
    CHECK(j["seams"]["count"] == 1);
    CHECK(j["seams"]["listed"][0]["length"] == Approx(1));
    CHECK(j["cracks"]["count"] == 6);
    CHECK(j["defects"] == 8);
    CHECK(j["components"] == 1); // the T-junction's two sides join the pieces into one shell
    CHECK(j["shell_contacts"]["count"] == 0);
    CHECK(j["closed"] == false);
    CHECK(j["passed"] == false);
    // The two pieces' seam vertices coincide: welded, then judged.
    CHECK(j["welded_vertices"] > 0);
    r = test::run_cli("check \"" + (dir / "tj.glb").string() + "\" --no-weld");
    CHECK(r.status == 1);
    test::write_file(dir / "bad.off", "OFF\n3 1 0\n0 0 0\n");
    r = test::run_cli("check \"" + (dir / "bad.off").string() + "\"");
    CHECK(r.status == 2);
    CHECK(r.err.rfind("error: ", 0) == 0);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(r.err.find("bad.off") != std::string::npos);
    r = test::run_cli("check \"" + (dir / "missing.stl").string() + "\"");
    CHECK(r.status == 2);
}
