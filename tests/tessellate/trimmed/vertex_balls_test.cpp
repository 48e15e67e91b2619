// SPDX-License-Identifier: MIT
// A vertex stands for its tolerance ball: polyline points inside it beside
// the vertex are dropped, and a solid whose edge's curve starts behind its
// vertex (within the vertex's tolerance, as pyocc_11752's edge #21222 does)
// comes out closed with no triangle folded against its surface.
#include <tessellate/mesh_properties.h>
#include <tessellate/trimmed/brep_builder.h>
#include <tessellate/trimmed/brep_cases.h>

#include <seamless/tessellate/tessellation.h>
#include <seamless/tessellate/trimmed/vertex_balls.h>

#include <catch2/catch.hpp>

using namespace seamless;
using namespace seamless::test;

namespace {

// The polyline of edge e through the given parameters of its curve, ends at
// its vertices.
EdgePolyline polyline(const BRep& brep, int e, const std::vector<double>& t) {
    EdgePolyline line;
    line.t = t;
    for (double x : t) line.points.push_back(evaluate_point(brep.curves[brep.edges[e].curve], x));
    line.points.front() = brep.vertices[brep.edges[e].start].point;
    line.points.back() = brep.vertices[brep.edges[e].end].point;
    return line;
}

// The unit box whose three edges at the origin start at q, 5e-7 behind the
// origin along -x (the vertex stays at the origin, its tolerance 1e-5), and
// whose x edge has a kink 4e-7 behind it: its polyline steps back from the
// vertex to the kink before running forward.
Model box_with_curves_behind_a_vertex() {
    Model m = box_solid().model;
    BRep& b = m.brep;
    int origin = -1;
    for (size_t v = 0; v < b.vertices.size(); ++v)
        if (b.vertices[v].point == Vec3{}) origin = static_cast<int>(v);
    b.vertices[origin].tolerance = 1e-5;
    const Vec3 q{-5e-7, 0, 0};
    for (size_t e = 0; e < b.edges.size(); ++e) {
        BRepEdge& edge = b.edges[e];
        if (edge.start != origin && edge.end != origin) continue;
        edge.tolerance = 1e-6; // the tilted y and z edges stray from two planes by 5e-7
        BSplineCurve& c = b.curves[edge.curve];
        const bool along_x = c.points.front().x != c.points.back().x;
        (edge.start == origin ? c.points.front() : c.points.back()) = q;
        if (along_x && edge.start == origin) {
            c.knots = {0, 0, 1e-7, 1, 1};
            c.points.insert(c.points.begin() + 1, Vec3{-4e-7, 0, 0});
        }
    }
    // Pcurves: the planes' images of the new curves.
    for (BRepFace& f : b.faces) {
        const BSplineSurface& s = m.surfaces[f.surface];
        const Vec3 o = evaluate_point(s, 0, 0);
        const PlaneFrame frame{o, evaluate_point(s, 1, 0) - o, evaluate_point(s, 0, 1) - o};
        for (BRepLoop& loop : f.loops)
            for (BRepCoedge& c : loop.coedges)
                b.pcurves[c.pcurve] = frame.pcurve(b.curves[b.edges[c.edge].curve]);
    }
    return m;
}

} // namespace

TEST_CASE("vertex balls: points within a vertex's tolerance beside it are dropped", "[brep]") {
    BRepBuilder b;
    const int v0 = b.vertex({0, 0, 0}), v1 = b.vertex({1, 0, 0});
    b.m.brep.vertices[v0].tolerance = 1e-5;
    b.m.brep.vertices[v1].tolerance = 1e-3;
    const int e = b.edge(nurbs_line({0, 0, 0}, {1, 0, 0}), v0, v1);
    const BRep& brep = b.m.brep;
    const std::vector<double> t{0, 2e-6, 8e-6, 0.5, 0.9995, 1};
    EdgePolyline line = polyline(brep, e, t);
    drop_points_in_vertex_balls(brep, e, line, 1.0);
    CHECK(line.t == std::vector<double>{0, 0.5, 1});
    CHECK(line.points.size() == line.t.size());
    CHECK(line.points[1] == Vec3{0.5, 0, 0});
    // A ball is at most a hundredth of D wide.
    line = polyline(brep, e, t);
    drop_points_in_vertex_balls(brep, e, line, 0.01);
    CHECK(line.t == std::vector<double>{0, 0.5, 0.9995, 1});
    line = polyline(brep, e, t);
    drop_points_in_vertex_balls(brep, e, line, 5e-4);
    CHECK(line.t == std::vector<double>{0, 8e-6, 0.5, 0.9995, 1});
}

TEST_CASE("vertex balls: a closed edge keeps three segments", "[brep]") {
    BRepBuilder b;
    const int v = b.vertex({2, 0, 0});
    b.m.brep.vertices[v].tolerance = 10;
    const int e = b.edge(nurbs_circle({}, 2, {1, 0, 0}, {0, 1, 0}), v, v);
    const std::vector<double> t{0, 1, 2, 3, 4};
    EdgePolyline line = polyline(b.m.brep, e, t);
    drop_points_in_vertex_balls(b.m.brep, e, line, 1e6);
    CHECK(line.t == t);
}

TEST_CASE("vertex balls: an edge whose curve starts behind its vertex does not fold the mesh",
          "[brep]") {
    const Model m = box_with_curves_behind_a_vertex();
    const Tessellation t = tessellate(m, {});
    const TriangleMesh& mesh = t.mesh;
    const MeshReport r = analyse_mesh(mesh, 1);
    CHECK(r.border_edges == 0);
    CHECK(r.nonmanifold_edges == 0);
    CHECK(r.misoriented_edges == 0);
    CHECK(r.euler() == 2);
    // Every triangle faces the way its surface does: a polyline folded at
    // the vertex makes a triangle there run back over its neighbours.
    int folded = 0;
    for (size_t k = 0; k < mesh.triangles.size(); ++k) {
        const auto& c = mesh.triangles[k];
        const Vec3 a = mesh.positions[c[0]], p = mesh.positions[c[1]], q = mesh.positions[c[2]];
        const Vec3 n = cross(p - a, q - a);
        for (const Vec3& corner : mesh.corner_normals[k])
            if (!(dot(n, corner) > 0)) ++folded;
    }
    CHECK(folded == 0);
}
