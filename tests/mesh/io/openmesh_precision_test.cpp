// SPDX-License-Identifier: MIT
// Why lib/mesh/io/mesh_io.cpp writes OFF/OBJ/PLY/STL itself instead of through
// OpenMesh: OpenMesh 9 passes points through Vec3f even for a double mesh and a
// precision of 17 digits, so a round trip loses everything past float. Our
// writer and reader round-trip the same coordinates bit for bit. If a future
// OpenMesh keeps doubles, the first CHECK fails and the hand-written code can go.
#include "test_util.h"

#include <seamless/mesh/io/mesh_io.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <catch2/catch.hpp>

using namespace seamless;

namespace {
struct DoubleTraits : OpenMesh::DefaultTraits {
    typedef OpenMesh::Vec3d Point;
    typedef OpenMesh::Vec3d Normal;
};
using DMesh = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;
} // namespace

TEST_CASE("OpenMesh rounds to float; our OFF writer keeps doubles", "[mesh_io][openmesh]") {
    const auto dir = test::scratch_dir("openmesh-precision");
    const double xs[3] = {0.1, 1.0 / 3.0, 2.718281828459045};
    DMesh m;
    std::vector<DMesh::VertexHandle> vh;
    for (double x : xs) vh.push_back(m.add_vertex(DMesh::Point(x, 2 * x, 3 * x)));
    m.add_face(vh);
    const std::string om = (dir / "openmesh.off").string();
    REQUIRE(OpenMesh::IO::write_mesh(m, om, OpenMesh::IO::Options::Default, 17));
    DMesh back;
    REQUIRE(OpenMesh::IO::read_mesh(back, om));
    bool exact = true;
    int k = 0;
    for (auto v : back.vertices()) exact &= back.point(v)[0] == xs[k++];
    CHECK_FALSE(exact); // OpenMesh lost precision

    TriangleMesh t;
    for (double x : xs) t.positions.push_back({x, 2 * x, 3 * x});
    t.triangles.push_back({0, 1, 2});
    write_mesh(dir / "ours.off", t);
    const TriangleMesh r = read_mesh(dir / "ours.off");
    REQUIRE(r.positions.size() == 3);
    for (int i = 0; i < 3; ++i) CHECK(r.positions[i] == t.positions[i]);
}
