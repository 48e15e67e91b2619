// SPDX-License-Identifier: MIT
// Trimmed B-rep faces (issue 28, section 2) on hand-made hard cases
// (brep_cases.h): solids come out closed with their Euler characteristic,
// no triangle is degenerate, the flat triangles are within the deviation of
// the exact (analytic) surfaces and the NURBS's points at their (u,v) within
// it, or where larger the certified bound, of their triangles (a long
// triangle's (u,v) image strays from it towards a neighbour's), the mesh is
// byte-identical on one and two threads, and faces share their boundary
// vertices.
#include <tessellate/mesh_properties.h>
#include <tessellate/trimmed/brep_cases.h>

#include <seamless/base/segment_distance.h>
#include <seamless/tessellate/tessellation.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace seamless;
using namespace seamless::test;

namespace {

constexpr double kSamples[][3] = {
    {1.0 / 3, 1.0 / 3, 1.0 / 3}, {0.6, 0.2, 0.2},   {0.2, 0.6, 0.2},   {0.2, 0.2, 0.6},
    {0.45, 0.45, 0.1},           {0.1, 0.45, 0.45}, {0.45, 0.1, 0.45}, {0.8, 0.1, 0.1}};

// Poles and apexes: every (u,v) along their degenerate edge is the vertex,
// and near them the (u,v) image of a triangle strays far from it: only the
// analytic distance measures those.
bool has_poles(const Model& m) {
    for (const BRepEdge& e : m.brep.edges)
        if (e.degenerate()) return true;
    return false;
}

// Distance of p to the triangle abc: its nearest point in the plane by
// least squares on the barycentric coordinates, or on the nearest side.
double to_triangle(Vec3 p, Vec3 a, Vec3 b, Vec3 c) {
    // In units of the triangle's size: products of coordinates near
    // 1e+-150 leave doubles.
    const double size = std::max(norm(b - a), norm(c - a));
    if (!(size > 0)) return distance(p, a);
    const Vec3 e = (b - a) / size, f = (c - a) / size, r = (p - a) / size;
    const double ee = dot(e, e), ef = dot(e, f), ff = dot(f, f), det = ee * ff - ef * ef;
    if (det > 0) {
        const double s = (ff * dot(r, e) - ef * dot(r, f)) / det,
                     t = (ee * dot(r, f) - ef * dot(r, e)) / det;
        if (s >= 0 && t >= 0 && s + t <= 1) return size * norm(r - s * e - t * f);
    }
    return std::min({point_segment_distance(p, a, b), point_segment_distance(p, b, c),
                     point_segment_distance(p, c, a)});
}

struct Deviation {
    double analytic = 0, through_uv = 0;
};

Deviation measure(const BRepCase& c, const TriangleMesh& m) {
    Deviation d;
    const bool pole = has_poles(c.model);
    for (int t = 0; t < m.triangle_count(); ++t) {
        const auto& tri = m.triangles[t];
        const BSplineSurface& s = c.model.surfaces[m.triangle_surface[t]];
        for (const auto& l : kSamples) {
            Vec3 p{}, uv{};
            for (int k = 0; k < 3; ++k) {
                p += l[k] * m.positions[tri[k]];
                uv += l[k] * Vec3{m.corner_uvs[t][k][0], m.corner_uvs[t][k][1], 0};
            }
            d.analytic = std::max(d.analytic, c.distance(m.triangle_surface[t], p));
            if (!pole) {
                // Loops across a seam have (u,v) beyond the domain, by a period.
                const double period = s.u_max() - s.u_min();
                bool closed = true; // in u: the loops may cross its seam
                for (int j = 0; j < s.size_v; ++j)
                    closed = closed && s.point(0, j) == s.point(s.size_u - 1, j);
                const double u = uv.x <= s.u_max() || !closed ? uv.x : uv.x - period;
                // Beyond an open side the surface is the tessellator's extension.
                if (u < s.u_min() || uv.y < s.v_min() || uv.y > s.v_max()) continue;
                d.through_uv = std::max(d.through_uv,
                                        to_triangle(evaluate(s, u, uv.y).point, m.positions[tri[0]],
                                                    m.positions[tri[1]], m.positions[tri[2]]));
            }
        }
    }
    return d;
}

template <class T> bool same_bytes(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

void check_case(const BRepCase& c, const TessellationOptions& options) {
    INFO(c.name);
    TessellationOptions o = options;
    o.threads = 1;
    const Tessellation t = tessellate(c.model, o);
    const TriangleMesh& m = t.mesh;
    const double D = t.stats.tolerance;
    REQUIRE(m.triangle_count() > 0);
    CHECK(t.stats.brep.faces == static_cast<int>(c.model.brep.faces.size()));
    // At unit scale (a power of two, exact): the checks square coordinates.
    TriangleMesh unit = m;
    const double down = std::ldexp(1.0, -std::ilogb(t.stats.d_max));
    for (Vec3& p : unit.positions) p = down * p;
    const MeshReport r = analyse_mesh(unit, t.stats.d_max * down);
    INFO(r.example);
    CHECK(r.zero_area == 0);
    CHECK(r.duplicate_positions == 0);
    CHECK(r.nonmanifold_edges == 0);
    CHECK(r.misoriented_edges == 0);
    CHECK(r.t_junctions == 0);
    CHECK(r.euler() == c.euler);
    if (c.closed) {
        CHECK(r.border_edges == 0);
        CHECK(count_shells(m) == 1);
    }
    // Normals: unit, on the triangle's outward side.
    for (int i = 0; i < m.triangle_count(); ++i) {
        const auto& tri = m.triangles[i];
        // Unit sides first: squares of coordinates near 1e+-150 leave doubles.
        const Vec3 n = cross(normalize(m.positions[tri[1]] - m.positions[tri[0]]),
                             normalize(m.positions[tri[2]] - m.positions[tri[0]]));
        for (const Vec3& cn : m.corner_normals[i]) {
            CHECK(std::abs(norm(cn) - 1) < 1e-9);
            CHECK(dot(cn, n) > 0);
        }
    }
    const Deviation d = measure(c, m);
    INFO("D " << D << ", bound " << t.stats.max_error_bound << ", analytic " << d.analytic
              << ", through (u,v) " << d.through_uv << ", reported " << t.stats.brep.max_deviation);
    CHECK(d.analytic <= D);
    CHECK(d.through_uv <= std::max(D, t.stats.max_error_bound));
    CHECK(t.stats.brep.max_deviation <= D);
    o.threads = 2;
    const Tessellation t2 = tessellate(c.model, o);
    CHECK(same_bytes(m.positions, t2.mesh.positions));
    CHECK(same_bytes(m.triangles, t2.mesh.triangles));
    CHECK(same_bytes(m.corner_normals, t2.mesh.corner_normals));
    CHECK(same_bytes(m.corner_uvs, t2.mesh.corner_uvs));
    CHECK(same_bytes(m.triangle_surface, t2.mesh.triangle_surface));
}

} // namespace

TEST_CASE("trimmed faces: a plate with a hole, light", "[brep]") {
    check_case(plate_with_holes(1), {});
}

TEST_CASE("trimmed faces: the hard cases at 1e-3 of the diagonal", "[brep][heavy]") {
    for (const BRepCase& c : all_brep_cases()) check_case(c, {});
}

TEST_CASE("trimmed faces: the solids at 1e-4 of the diagonal", "[brep][heavy]") {
    for (const BRepCase& c :
         {box_solid(), cylinder_solid(), cone_solid(), sphere_solid(), torus_solid()}) {
        TessellationOptions o;
        o.tolerance = 1e-4 * norm(control_box(c.model).extent());
        check_case(c, o);
    }
}

TEST_CASE("trimmed faces: a face whose only edge is degenerate is a point, meshed as nothing",
          "[brep][heavy]") {
    // A collapsed face (as real files have): the cone's apex bounded by the
    // degenerate tip edge alone.
    BRepCase c = cone_solid();
    BRep& b = c.model.brep;
    int tip = -1;
    for (size_t e = 0; e < b.edges.size(); ++e)
        if (b.edges[e].degenerate()) tip = static_cast<int>(e);
    REQUIRE(tip >= 0);
    BSplineCurve along_apex;
    along_apex.degree = 1;
    along_apex.knots = {0, 0, 4, 4};
    along_apex.points = {{0, 1, 0}, {4, 1, 0}};
    b.pcurves.push_back(along_apex);
    BRepFace apex;
    apex.surface = b.faces[0].surface;
    apex.name = "#apex";
    apex.loops.push_back({{{tip, false, static_cast<int>(b.pcurves.size()) - 1}}});
    b.faces.push_back(apex);
    b.shells[0].faces.push_back(static_cast<int>(b.faces.size()) - 1);
    const Tessellation with = tessellate(c.model, {});
    const Tessellation without = tessellate(cone_solid().model, {});
    CHECK(with.mesh.triangle_count() == without.mesh.triangle_count());
    CHECK(with.stats.brep.faces_left_out == 0);
    const MeshReport r = analyse_mesh(with.mesh, 1);
    CHECK(r.border_edges == 0);
    CHECK(r.euler() == 2);
}

TEST_CASE("trimmed faces: adjacent faces share their boundary vertices", "[brep]") {
    const BRepCase c = cylinder_solid();
    const Tessellation t = tessellate(c.model, {});
    const TriangleMesh& m = t.mesh;
    // Every mesh vertex on a circle edge is used by triangles of the lateral
    // face and of the disk: one index, not a copy per face.
    std::vector<std::vector<int>> faces_at(m.vertex_count());
    for (int i = 0; i < m.triangle_count(); ++i)
        for (int k : m.triangles[i]) faces_at[k].push_back(m.triangle_surface[i]);
    int on_edges = 0;
    for (int v = 0; v < m.vertex_count(); ++v) {
        const Vec3 p = m.positions[v];
        if (!((p.z == 0 || p.z == 2) && std::abs(std::hypot(p.x, p.y) - 1) < 1e-9)) continue;
        ++on_edges;
        std::vector<int>& f = faces_at[v];
        std::sort(f.begin(), f.end());
        f.erase(std::unique(f.begin(), f.end()), f.end());
        CHECK(f.size() == 2);
    }
    CHECK(on_edges == t.stats.brep.edge_points + 2);
    CHECK(analyse_mesh(m, 1).border_edges == 0);
}

TEST_CASE("trimmed faces: a face whose loops cross fails by name, or is left out",
          "[brep][heavy]") {
    const BRepCase c = crossing_loops();
    REQUIRE_THROWS_WITH(tessellate(c.model, {}), Catch::Contains("#crossing"));
    TessellationOptions o;
    o.allow_holes = true;
    const Tessellation t = tessellate(c.model, o);
    CHECK(t.mesh.triangle_count() == 0);
    CHECK(t.stats.brep.faces_left_out == 1);
    REQUIRE(t.stats.brep.warnings.size() == 1);
    CHECK_THAT(t.stats.brep.warnings[0], Catch::Contains("#crossing"));
}

TEST_CASE("trimmed faces: a sliver's coincident chords are re-split on both sides", "[brep]") {
    // The arc's first chord is the line: the loop's two segments overlap.
    TessellationOptions o;
    o.tolerance = 1e-2;
    const Tessellation t = tessellate(sliver_face(1e-3).model, o);
    CHECK(t.stats.brep.resplit_rounds >= 1);
    const MeshReport r = analyse_mesh(t.mesh, 1);
    CHECK(r.zero_area == 0);
    CHECK(r.euler() == 1);
}

TEST_CASE("trimmed faces: edge tolerances above D are reported", "[brep][heavy]") {
    BRepCase c = cylinder_solid();
    for (BRepEdge& e : c.model.brep.edges) e.tolerance = 0.01;
    TessellationOptions o;
    o.tolerance = 1e-3;
    const Tessellation t = tessellate(c.model, o);
    CHECK(t.stats.brep.edges_above_tolerance == 3);
    CHECK(t.stats.brep.max_edge_tolerance == 0.01);
    CHECK(!t.stats.brep.warnings.empty());
    CHECK(analyse_mesh(t.mesh, 1).border_edges == 0);
}

TEST_CASE("trimmed faces: the triangle budget is enforced", "[brep]") {
    TessellationOptions o;
    o.max_triangles = 50;
    CHECK_THROWS_AS(tessellate(sphere_solid().model, o), TriangleBudgetError);
}
