// SPDX-License-Identifier: MIT
// TriangleMesh <-> OpenMesh (lib/mesh/openmesh.h): round trips keep every bit,
// what OpenMesh cannot hold is refused by name.
#include "mesh/convert/same_mesh.h"

#include <seamless/mesh/openmesh.h>

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

using namespace seamless;

TEST_CASE("The teapot through OpenMesh and back, bit for bit", "[openmesh][heavy]") {
    const TriangleMesh& mesh = test::teapot_mesh();
    REQUIRE(!mesh.corner_normals.empty());
    REQUIRE(!mesh.triangle_surface.empty());
    const OpenMeshTriMesh om = to_openmesh(mesh);
    // The handle touches the body at one vertex: a copy per extra fan.
    const size_t copies = copy_pinched_vertices(mesh).copy_of.size();
    CHECK(copies >= 1);
    REQUIRE(om.n_vertices() == mesh.positions.size() + copies);
    OpenMesh::VPropHandleT<OpenMeshTriMesh::VertexHandle> copy_of;
    CHECK(om.get_property_handle(copy_of, kOpenMeshCopyOfProperty));
    REQUIRE(int(om.n_faces()) == mesh.triangle_count());
    // OpenMesh itself holds the doubles, not only the way back.
    for (int i = 0; i < mesh.vertex_count(); ++i) {
        const auto& p = om.point(om.vertex_handle(i));
        CHECK(test::same_bytes(Vec3{p[0], p[1], p[2]}, mesh.positions[i]));
    }
    CHECK(om.has_halfedge_normals());
    test::check_same_mesh(from_openmesh(om), mesh, true);
}

TEST_CASE("An empty mesh through OpenMesh", "[openmesh]") {
    const OpenMeshTriMesh om = to_openmesh(TriangleMesh{});
    CHECK(om.n_vertices() == 0);
    CHECK(om.n_faces() == 0);
    test::check_same_mesh(from_openmesh(om), TriangleMesh{}, true);
}

TEST_CASE("What OpenMesh cannot hold is refused, naming the triangle", "[openmesh]") {
    using Catch::Matchers::Contains;
    // A third face on an edge: OpenMesh's "complex edge".
    CHECK_THROWS_WITH(to_openmesh(test::three_faces_on_an_edge()),
                      Contains("triangles[2]") && Contains("non-manifold"));
    // The same directed edge in two faces (opposite orientations).
    TriangleMesh flipped = test::three_faces_on_an_edge();
    flipped.triangles = {{0, 1, 2}, {0, 1, 3}};
    CHECK_THROWS_WITH(to_openmesh(flipped), Contains("triangles[1]"));
    TriangleMesh bad = flipped;
    bad.triangles = {{0, 1, 2}, {3, 3, 4}};
    CHECK_THROWS_WITH(to_openmesh(bad), Contains("triangles[1]") && Contains("repeats"));
    bad.triangles = {{0, 1, 5}};
    CHECK_THROWS_WITH(to_openmesh(bad), Contains("triangles[0]") && Contains("out of range"));
    bad.triangles = {{0, 1, 2}};
    bad.corner_normals.resize(2);
    CHECK_THROWS_WITH(to_openmesh(bad), Contains("corner_normals"));
}

TEST_CASE("A mesh without attributes comes back without them", "[openmesh]") {
    TriangleMesh m = test::three_faces_on_an_edge();
    m.triangles.pop_back();
    test::check_same_mesh(from_openmesh(to_openmesh(m)), m, true);
}

TEST_CASE("A polygon mesh's quad is refused by name; float points widen exactly", "[openmesh]") {
    OpenMesh::PolyMesh_ArrayKernelT<> poly; // OpenMesh's default: float points
    std::vector<OpenMesh::PolyMesh_ArrayKernelT<>::VertexHandle> v;
    for (float x : {0.1f, 1.0f, 1.0f, 0.0f}) v.push_back(poly.add_vertex({x, x * x, 0.3f}));
    poly.add_face(v[0], v[1], v[2]);
    const TriangleMesh one = from_openmesh(poly);
    REQUIRE(one.vertex_count() == 4);
    CHECK(one.positions[0].x == double(0.1f));
    CHECK(one.positions[0].z == double(0.3f));
    poly.add_face(v[0], v[2], v[3]);
    poly.add_face(v[3], v[2], v[1], v[0]); // the back: a quad
    CHECK_THROWS_WITH(from_openmesh(poly), Catch::Matchers::Contains("faces[2]"));
}

TEST_CASE("OpenMesh: a vertex of two fans is split and merged again", "[openmesh]") {
    const TriangleMesh m = test::bowtie();
    test::check_same_mesh(from_openmesh(to_openmesh(m)), m, false);
}
