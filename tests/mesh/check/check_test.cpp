// SPDX-License-Identifier: MIT
#include "test_util.h"

#include <seamless/base/error.h>
#include <seamless/mesh/check/check.h>
#include <seamless/mesh/io/mesh_io.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <cmath>
#include <cstring>
#include <map>

using namespace seamless;

namespace {

// A piece of the surface z = 0.3 sin(2x) over [x0, x1] x [0, 1] with its own
// vertices, nx by ny quads, shifted by `offset`. Two pieces meeting at the same x
// have bit-identical seam positions (same formula, same inputs).
void add_piece(TriangleMesh& m, double x0, double x1, int nx, int ny, Vec3 offset = {}) {
    const int base = m.vertex_count();
    for (int i = 0; i <= nx; ++i)
        for (int j = 0; j <= ny; ++j) {
            const double x = x0 + i * ((x1 - x0) / nx), y = static_cast<double>(j) / ny;
            m.positions.push_back(Vec3{x, y, 0.3 * std::sin(2 * x)} + offset);
        }
    auto id = [&](int i, int j) { return base + i * (ny + 1) + j; };
    for (int i = 0; i < nx; ++i)
        for (int j = 0; j < ny; ++j) {
            m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
}

TriangleMesh octahedron(Vec3 c = {}, double r = 1) {
    TriangleMesh m;
    for (Vec3 d : {Vec3{1, 0, 0}, Vec3{-1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, -1, 0}, Vec3{0, 0, 1},
                   Vec3{0, 0, -1}})
        m.positions.push_back(c + r * d);
    // Outward: counter-clockwise seen from outside.
    m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                   {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    return m;
}

void append(TriangleMesh& m, const TriangleMesh& other) {
    const int base = m.vertex_count();
    m.positions.insert(m.positions.end(), other.positions.begin(), other.positions.end());
    for (auto t : other.triangles) m.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
}

// A strip of width 1 in y swept along a polyline in the xz-plane, each segment
// cut into `cuts[k]` pieces; consistently oriented and manifold.
TriangleMesh sweep(const std::vector<std::array<double, 2>>& path, const std::vector<int>& cuts) {
    std::vector<std::array<double, 2>> pts{path[0]};
    for (size_t k = 0; k + 1 < path.size(); ++k)
        for (int s = 1; s <= cuts[k]; ++s) {
            const double t = static_cast<double>(s) / cuts[k];
            pts.push_back({path[k][0] + t * (path[k + 1][0] - path[k][0]),
                           path[k][1] + t * (path[k + 1][1] - path[k][1])});
        }
    TriangleMesh m;
    for (auto p : pts) {
        m.positions.push_back({p[0], 0, p[1]});
        m.positions.push_back({p[0], 1, p[1]});
    }
    for (int i = 0; i + 1 < static_cast<int>(pts.size()); ++i) {
        m.triangles.push_back({2 * i, 2 * i + 2, 2 * i + 3});
        m.triangles.push_back({2 * i, 2 * i + 3, 2 * i + 1});
    }
    return m;
}

// The names of the defect kinds the report holds.
std::vector<std::string> defects(const CheckReport& r) {
    std::vector<std::string> d;
    if (!r.cracks.empty()) d.push_back("cracks");
    if (!r.t_junctions.empty()) d.push_back("t_junctions");
    if (!r.non_manifold_edges.empty()) d.push_back("non_manifold_edges");
    if (!r.non_manifold_vertices.empty()) d.push_back("non_manifold_vertices");
    if (!r.degenerate_triangles.empty()) d.push_back("degenerate_triangles");
    if (!r.duplicated_triangles.empty()) d.push_back("duplicated_triangles");
    if (!r.inconsistent_orientation.empty()) d.push_back("inconsistent_orientation");
    if (!r.self_intersections.empty()) d.push_back("self_intersections");
    return d;
}
using Names = std::vector<std::string>;

// CGAL's own view of a manifold mesh: vertices welded as check does (bit-identical
// positions) unless `weld` is false; returns {border halfedges, is_closed}.
std::pair<int, bool> cgal_borders(const TriangleMesh& m, bool weld) {
    using P = CGAL::Simple_cartesian<double>::Point_3;
    CGAL::Surface_mesh<P> sm;
    std::map<std::array<double, 3>, CGAL::Surface_mesh<P>::Vertex_index> by_pos;
    std::vector<CGAL::Surface_mesh<P>::Vertex_index> vid;
    for (Vec3 p : m.positions) {
        std::array<double, 3> k{p.x, p.y, p.z};
        if (!weld || !by_pos.count(k)) by_pos[k] = sm.add_vertex(P(p.x, p.y, p.z));
        vid.push_back(weld ? by_pos[k]
                           : CGAL::Surface_mesh<P>::Vertex_index(sm.num_vertices() - 1));
    }
    for (auto t : m.triangles) {
        auto f = sm.add_face(vid[t[0]], vid[t[1]], vid[t[2]]);
        REQUIRE(f != CGAL::Surface_mesh<P>::null_face());
    }
    int border = 0;
    for (auto h : sm.halfedges()) border += sm.is_border(h);
    return {border, CGAL::is_closed(sm)};
}

void agrees_with_cgal(const TriangleMesh& m, const CheckReport& r, bool weld = true) {
    auto [border, closed] = cgal_borders(m, weld);
    CHECK(r.border_edges == border);
    CHECK(r.closed == closed);
}

} // namespace

TEST_CASE("check: a seam of coincident unshared vertices is welded, or a crack of gap 0") {
    TriangleMesh m;
    add_piece(m, 0, 0.5, 2, 4);
    add_piece(m, 0.5, 1, 2, 4);
    const CheckReport r = check_mesh(m);
    CHECK(r.welded_vertices == 5);
    CHECK(defects(r) == Names{});
    CHECK(r.components.size() == 1);
    CHECK(r.border_loops.size() == 1);
    CHECK(r.border_loops[0].edges == 16);
    // Two sides of length 1 plus the curve z = 0.3 sin(2x) twice (chords: a bit over 1).
    CHECK(r.border_loops[0].length > 4);
    CHECK(r.border_loops[0].length < 4.5);
    CHECK(r.border_loops[0].closed);
    agrees_with_cgal(m, r);

    CheckOptions raw;
    raw.weld = false;
    const CheckReport n = check_mesh(m, raw);
    CHECK(n.welded_vertices == 0);
    CHECK(defects(n) == Names{"cracks"});
    CHECK(n.cracks.size() == 8); // 4 seam edges on either side
    CHECK(n.widest_crack == 0);
    CHECK(n.components.size() == 2);
    agrees_with_cgal(m, n, false);
}

TEST_CASE("check: a T-junction") {
    TriangleMesh m;
    add_piece(m, 0, 0.5, 2, 2);
    add_piece(m, 0.5, 1, 2, 4);
    const CheckReport r = check_mesh(m);
    // The seam's 2 + 4 edges run along each other: crack edges of one seam, with
    // the T-junctions where the finer side's vertices lie inside the coarser edges.
    CHECK(defects(r) == Names{"cracks", "t_junctions"});
    CHECK(r.cracks.size() == 6);
    REQUIRE(r.seams.size() == 1);
    CHECK(r.seams[0].length == Approx(1));
    CHECK(r.seams[0].location.x == 0.5);
    CHECK(r.components.size() == 1); // the sides share the seam's ends and middle
    REQUIRE(r.t_junctions.size() == 2);
    CHECK(r.t_junctions[0].position.x == 0.5);
    CHECK((r.t_junctions[0].position.y == 0.25 || r.t_junctions[0].position.y == 0.75));
    CHECK(r.t_junctions[0].distance < 1e-12);
    agrees_with_cgal(m, r);
}

TEST_CASE("check: gaps below the tolerance are cracks, above it plain borders") {
    const double d_max = 1.0; // the pieces span x in [0, 1 + tiny]
    SECTION("gap 1e-7 * d_max: a crack by default") {
        TriangleMesh m;
        add_piece(m, 0, 0.5, 2, 4);
        add_piece(m, 0.5, 1, 2, 4, {1e-7 * d_max, 0, 0});
        const CheckReport r = check_mesh(m);
        CHECK(r.welded_vertices == 0);
        CHECK(defects(r) == Names{"cracks"});
        CHECK(r.cracks.size() == 8);
        CHECK(r.widest_crack == Approx(1e-7).epsilon(1e-6));
        agrees_with_cgal(m, r);
    }
    SECTION("gap 1e-4 (0.04% of the seam edges): a crack by default, a border with --gap 1e-5") {
        TriangleMesh m;
        add_piece(m, 0, 0.5, 2, 4);
        add_piece(m, 0.5, 1, 2, 4, {1e-4 * d_max, 0, 0});
        const CheckReport r = check_mesh(m);
        CHECK(defects(r) == Names{"cracks"});
        CHECK(r.cracks.size() == 8);
        CHECK(r.seams.size() == 1);
        CHECK(r.widest_crack == Approx(1e-4).epsilon(1e-6));
        agrees_with_cgal(m, r);
        CheckOptions tight;
        tight.gap = 1e-5 * r.d_max;
        const CheckReport t = check_mesh(m, tight);
        CHECK(defects(t) == Names{});
        CHECK(t.border_loops.size() == 2);
        CHECK(t.border_edges == 24);
    }
    SECTION("gap 0.01 (4% of the seam edges): a border by default, a crack with --gap 0.02") {
        TriangleMesh m;
        add_piece(m, 0, 0.5, 2, 4);
        add_piece(m, 0.5, 1, 2, 4, {0.01, 0, 0});
        const CheckReport r = check_mesh(m);
        CHECK(defects(r) == Names{});
        CHECK(r.border_loops.size() == 2);
        agrees_with_cgal(m, r);
        CheckOptions wide;
        wide.gap = 0.02;
        const CheckReport w = check_mesh(m, wide);
        CHECK(defects(w) == Names{"cracks"});
        CHECK(w.widest_crack == Approx(0.01).epsilon(1e-6));
    }
}

TEST_CASE("check: a closed octahedron") {
    const TriangleMesh m = octahedron();
    const CheckReport r = check_mesh(m);
    CHECK(defects(r) == Names{});
    CHECK(r.closed);
    CHECK(r.edges == 12);
    REQUIRE(r.components.size() == 1);
    const auto& c = r.components[0];
    CHECK(c.euler == 2);
    CHECK(c.genus == 0);
    REQUIRE(c.volume);
    CHECK(*c.volume == Approx(4.0 / 3.0));
    CHECK(c.outward == true);
    agrees_with_cgal(m, r);
    CheckOptions closed;
    closed.require_closed = true;
    CHECK(check_passed(r, closed));

    // Turned inside out: still no defect, but not outward and negative volume.
    TriangleMesh inv = m;
    for (auto& t : inv.triangles) std::swap(t[1], t[2]);
    const CheckReport ri = check_mesh(inv);
    CHECK(defects(ri) == Names{});
    CHECK(ri.components[0].outward == false);
    CHECK(*ri.components[0].volume == Approx(-4.0 / 3.0));
}

TEST_CASE("check: a torus has genus 1") {
    TriangleMesh m;
    const int nu = 12, nv = 8;
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            const double u = 2 * M_PI * i / nu, v = 2 * M_PI * j / nv;
            m.positions.push_back({(2 + 0.5 * std::cos(v)) * std::cos(u),
                                   (2 + 0.5 * std::cos(v)) * std::sin(u), 0.5 * std::sin(v)});
        }
    auto id = [&](int i, int j) { return (i % nu) * nv + (j % nv); };
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    const CheckReport r = check_mesh(m);
    CHECK(defects(r) == Names{});
    REQUIRE(r.components.size() == 1);
    CHECK(r.components[0].euler == 0);
    CHECK(r.components[0].genus == 1);
    CHECK(r.components[0].outward == true);
    CHECK(*r.components[0].volume > 0);
    agrees_with_cgal(m, r);
}

TEST_CASE("check: a flipped triangle") {
    TriangleMesh m = octahedron();
    std::swap(m.triangles[3][1], m.triangles[3][2]);
    const CheckReport r = check_mesh(m);
    CHECK(defects(r) == Names{"inconsistent_orientation"});
    CHECK(r.inconsistent_orientation.size() == 3);
    CHECK(r.closed);
    CHECK_FALSE(r.components[0].outward.has_value());
}

TEST_CASE("check: a non-manifold edge") {
    TriangleMesh m;
    m.positions = {{0, 0, 0}, {0, 0, 1}, {1, 0, 0.5}, {-1, 0.2, 0.5}, {0, -1, 0.5}};
    m.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
    const CheckReport r = check_mesh(m);
    CHECK(defects(r) == Names{"non_manifold_edges"});
    REQUIRE(r.non_manifold_edges.size() == 1);
    CHECK(r.non_manifold_edges[0].triangles == 3);
}

TEST_CASE("check: two shells touching at a vertex (a bowtie) are a shell contact") {
    TriangleMesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0.5}};
    m.triangles = {{0, 1, 2}, {0, 3, 4}};
    const CheckReport r = check_mesh(m);
    CHECK(defects(r) == Names{});
    CHECK(r.components.size() == 2);
    REQUIRE(r.shell_contacts.size() == 1);
    CHECK(r.shell_contacts[0].vertex == 0);
    CHECK(r.shell_contacts[0].position == Vec3{0, 0, 0});
    CHECK(r.overlaps.empty());                                 // touching at the shared vertex only
    for (const auto& c : r.components) CHECK(c.vertices == 3); // the contact counts in each
}

TEST_CASE("check: a shell pinched at a vertex is non-manifold") {
    // A planar ring of quads around the hole [-1, 1]^2, one quad (x in [1, 2],
    // y in [-1, 1]) replaced by two triangles meeting at its centre O: the ring,
    // one shell through its edges, touches itself at O and nowhere else.
    TriangleMesh m;
    const double xs[4] = {-2, -1, 1, 2};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) m.positions.push_back({xs[i], xs[j], 0});
    auto id = [](int i, int j) { return 4 * i + j; };
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            if (j == 1 && i >= 1) continue; // the hole and the pinched quad
            m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    const int o = m.vertex_count();
    m.positions.push_back({1.5, 0, 0});
    m.triangles.push_back({id(2, 1), id(3, 1), o});
    m.triangles.push_back({id(3, 2), id(2, 2), o});
    const CheckReport r = check_mesh(m);
    CHECK(defects(r) == Names{"non_manifold_vertices"});
    REQUIRE(r.non_manifold_vertices.size() == 1);
    CHECK(r.non_manifold_vertices[0].position == Vec3{1.5, 0, 0});
    CHECK(r.shell_contacts.empty());
    CHECK(r.components.size() == 1);
    CHECK(r.overlaps.empty());
}

TEST_CASE("check: a zero-area triangle") {
    TriangleMesh m;
    add_piece(m, 0, 1, 2, 2);
    const int b = m.vertex_count();
    m.positions.insert(m.positions.end(), {{0, 3, 0}, {1, 3, 0}, {2, 3, 0}});
    m.triangles.push_back({b, b + 1, b + 2});
    const CheckReport r = check_mesh(m);
    CHECK(defects(r) == Names{"degenerate_triangles"});
    REQUIRE(r.degenerate_triangles.size() == 1);
    CHECK(r.degenerate_triangles[0].triangle == m.triangle_count() - 1);
}

TEST_CASE("check: a duplicated triangle") {
    TriangleMesh m;
    add_piece(m, 0, 1, 2, 2);
    m.triangles.push_back(m.triangles[3]);
    const CheckReport r = check_mesh(m);
    const Names d = defects(r);
    CHECK(std::count(d.begin(), d.end(), "duplicated_triangles") == 1);
    REQUIRE(r.duplicated_triangles.size() == 1);
    CHECK(r.duplicated_triangles[0].t0 == 3);
}

TEST_CASE("check: a self-intersection inside one component") {
    // Out along z = 0, up, back over, and down through the first part at x = 2.5.
    const TriangleMesh m = sweep({{0, 0}, {4, 0}, {4, 1}, {2.5, 1}, {2.5, -1}}, {4, 1, 1, 3});
    const CheckReport r = check_mesh(m);
    CHECK(defects(r) == Names{"self_intersections"});
    CHECK(r.self_intersections.size() >= 2);
    CHECK(r.overlaps.empty());
    CHECK(r.components.size() == 1);
    agrees_with_cgal(m, r);
    // The same strip without the last segment does not intersect itself.
    const TriangleMesh ok = sweep({{0, 0}, {4, 0}, {4, 1}, {2.5, 1}}, {4, 1, 1});
    CHECK(defects(check_mesh(ok)) == Names{});
}

TEST_CASE("check: two overlapping closed components are no defect") {
    TriangleMesh m = octahedron();
    append(m, octahedron({0.5, 0.3, 0.2}, 0.8));
    const CheckReport r = check_mesh(m);
    CHECK(defects(r) == Names{});
    CHECK(r.components.size() == 2);
    CHECK_FALSE(r.overlaps.empty());
    CHECK(r.self_intersections.empty());
    for (const auto& c : r.components) {
        CHECK(c.closed);
        CHECK(c.euler == 2);
    }
    agrees_with_cgal(m, r);
}

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
