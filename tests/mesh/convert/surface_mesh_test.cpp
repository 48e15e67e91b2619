// SPDX-License-Identifier: MIT
// TriangleMesh <-> CGAL's Surface_mesh (lib/mesh/surface_mesh.h): round trips
// keep every bit, what Surface_mesh cannot hold is refused by name.
#include "mesh/convert/same_mesh.h"

#include <seamless/mesh/surface_mesh.h>

using namespace seamless;

TEST_CASE("The teapot through CGAL's Surface_mesh and back, bit for bit", "[surface_mesh][heavy]") {
    const TriangleMesh& mesh = test::teapot_mesh();
    REQUIRE(!mesh.corner_normals.empty());
    REQUIRE(!mesh.triangle_surface.empty());
    const CgalSurfaceMesh sm = to_surface_mesh(mesh);
    // The handle touches the body at one vertex: a copy per extra fan.
    const size_t copies = copy_pinched_vertices(mesh).copy_of.size();
    CHECK(copies >= 1);
    REQUIRE(sm.number_of_vertices() == mesh.positions.size() + copies);
    CHECK(sm.property_map<CgalSurfaceMesh::Vertex_index, CgalSurfaceMesh::Vertex_index>(
                kSurfaceMeshCopyOfMap)
              .second);
    REQUIRE(int(sm.number_of_faces()) == mesh.triangle_count());
    for (int i = 0; i < mesh.vertex_count(); ++i) {
        const auto& p = sm.point(CgalSurfaceMesh::Vertex_index(i));
        CHECK(test::same_bytes(Vec3{p.x(), p.y(), p.z()}, mesh.positions[i]));
    }
    CHECK(sm.is_valid(false));
    test::check_same_mesh(from_surface_mesh(sm), mesh, false); // names: no place in Surface_mesh
}

TEST_CASE("An empty mesh through Surface_mesh", "[surface_mesh]") {
    const CgalSurfaceMesh sm = to_surface_mesh(TriangleMesh{});
    CHECK(sm.number_of_vertices() == 0);
    CHECK(sm.number_of_faces() == 0);
    test::check_same_mesh(from_surface_mesh(sm), TriangleMesh{}, true);
}

TEST_CASE("What Surface_mesh cannot hold is refused, naming the triangle", "[surface_mesh]") {
    using Catch::Matchers::Contains;
    CHECK_THROWS_WITH(to_surface_mesh(test::three_faces_on_an_edge()),
                      Contains("triangles[2]") && Contains("non-manifold"));
    TriangleMesh flipped = test::three_faces_on_an_edge();
    flipped.triangles = {{0, 1, 2}, {0, 1, 3}};
    CHECK_THROWS_WITH(to_surface_mesh(flipped), Contains("triangles[1]"));
    flipped.triangles = {{0, 1, 2}, {2, 4, 2}};
    CHECK_THROWS_WITH(to_surface_mesh(flipped), Contains("triangles[1]") && Contains("repeats"));
}

TEST_CASE("A Surface_mesh's quad is refused by name; removed elements are skipped",
          "[surface_mesh]") {
    TriangleMesh m = test::three_faces_on_an_edge();
    m.triangles = {{0, 1, 2}, {1, 0, 3}};
    m.triangle_surface = {4, 7};
    CgalSurfaceMesh sm = to_surface_mesh(m);
    const auto isolated = sm.add_vertex({5, 5, 5});
    sm.remove_vertex(isolated);
    test::check_same_mesh(from_surface_mesh(sm), m, false);
    std::vector<CgalSurfaceMesh::Vertex_index> quad;
    for (double x : {10, 11})
        quad.push_back(sm.add_vertex({x, 0, 0})), quad.push_back(sm.add_vertex({x, 1, 0}));
    std::swap(quad[2], quad[3]);
    REQUIRE(sm.add_face(quad) != CgalSurfaceMesh::null_face()); // a quad beside the triangles
    CHECK_THROWS_WITH(from_surface_mesh(sm), Catch::Matchers::Contains("faces[2]"));
}

TEST_CASE("Surface_mesh: a vertex of two fans is split and merged again", "[surface_mesh]") {
    const TriangleMesh m = test::bowtie();
    test::check_same_mesh(from_surface_mesh(to_surface_mesh(m)), m, false);
}
