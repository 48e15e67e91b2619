// SPDX-License-Identifier: MIT
// check_mesh on the bundled models' tessellations (issue 4): written to .glb
// and .off with write_mesh, read back with read_mesh, no defects; the closed
// models closed with their Euler characteristic; border edges and closedness
// agree with CGAL's own Surface_mesh (is_closed, border halfedges).
#include "test_util.h"

#include <seamless/mesh/check/check.h>
#include <seamless/mesh/io/mesh_io.h>
#include <seamless/model/model.h>
#include <seamless/tessellate/tessellation.h>

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>
#include <map>
#include <set>
#include <sstream>

using namespace seamless;

namespace {

using SurfaceMesh = CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>;

struct Case {
    const char* name;
    bool closed = false;
    int euler = 0; // of the one component, when closed
};

// CGAL's view of the mesh, welded like check_mesh (bit-identical positions):
// a polygon soup that orient_polygon_soup makes a valid polygon mesh (it
// duplicates non-manifold vertices, which does not change the edges).
struct CgalCounts {
    bool built = false;
    int duplicated_points = 0; // non-manifold vertices split by orient_polygon_soup
    bool closed = false;
    int border_halfedges = 0;
};

CgalCounts cgal_counts(const TriangleMesh& m) {
    using Point = CGAL::Simple_cartesian<double>::Point_3;
    std::vector<Point> points;
    std::map<std::array<std::uint64_t, 3>, std::size_t> weld;
    std::vector<std::size_t> id(m.positions.size());
    for (size_t i = 0; i < m.positions.size(); ++i) {
        const Vec3 p = m.positions[i];
        std::array<std::uint64_t, 3> key{};
        std::memcpy(key.data(), &p.x, 8);
        std::memcpy(key.data() + 1, &p.y, 8);
        std::memcpy(key.data() + 2, &p.z, 8);
        auto [it, fresh] = weld.emplace(key, points.size());
        if (fresh) points.emplace_back(p.x, p.y, p.z);
        id[i] = it->second;
    }
    std::vector<std::vector<std::size_t>> polygons;
    for (const auto& f : m.triangles) polygons.push_back({id[f[0]], id[f[1]], id[f[2]]});
    const size_t before = points.size();
    namespace PMP = CGAL::Polygon_mesh_processing;
    PMP::orient_polygon_soup(points, polygons);
    CgalCounts c;
    c.duplicated_points = static_cast<int>(points.size() - before);
    if (!PMP::is_polygon_soup_a_polygon_mesh(polygons)) return c;
    SurfaceMesh sm;
    PMP::polygon_soup_to_polygon_mesh(points, polygons, sm);
    c.built = sm.number_of_faces() == m.triangles.size();
    c.closed = CGAL::is_closed(sm);
    for (auto h : sm.halfedges())
        if (sm.is_border(h)) ++c.border_halfedges;
    return c;
}

// The report's counts and first seam, for failure messages.
std::string summary(const CheckReport& r) {
    std::ostringstream s;
    s << "defects " << defect_count(r) << ": cracks " << r.cracks.size() << " in " << r.seams.size()
      << " seams, T-junctions " << r.t_junctions.size() << ", non-manifold edges "
      << r.non_manifold_edges.size() << ", vertices " << r.non_manifold_vertices.size()
      << ", degenerate " << r.degenerate_triangles.size() << ", duplicated "
      << r.duplicated_triangles.size() << ", misoriented " << r.inconsistent_orientation.size()
      << ", self-intersections " << r.self_intersections.size() << "; shells "
      << r.components.size() << ", border edges " << r.border_edges << ", widest crack "
      << r.widest_crack;
    if (!r.seams.empty())
        s << "; seam at (" << r.seams[0].location.x << ", " << r.seams[0].location.y << ", "
          << r.seams[0].location.z << ") length " << r.seams[0].length;
    return s.str();
}

CheckReport check_round_trip(const Model& m, const Case& c, const std::string& ext,
                             CgalCounts* cgal = nullptr) {
    const Tessellation t = tessellate(m, {});
    const auto dir = test::scratch_dir(std::string("bundled-") + c.name + ext.substr(1));
    const auto path = dir / (std::string(c.name) + ext);
    write_mesh(path, t.mesh);
    const TriangleMesh back = read_mesh(path);
    REQUIRE(back.triangle_count() == t.mesh.triangle_count());
    if (ext == ".off") CHECK(back.positions == t.mesh.positions); // 17 digits: bit-identical
    CheckOptions opt;
    opt.require_closed = c.closed;
    if (cgal) *cgal = cgal_counts(back);
    return check_mesh(back, opt);
}

} // namespace

TEST_CASE("bundled models tessellate into meshes check passes, through .glb and .off",
          "[check][bundled][heavy]") {
    const std::vector<Case> cases{{"torus", true, 0},       {"sphere", true, 2},
                                  {"torus_exact", true, 0}, {"quarter_cylinder"},
                                  {"repeated_knot"},        {"bilinear"}};
    for (const Case& c : cases)
        for (const std::string ext : {".glb", ".off"}) {
            const Model m = load_model(test::model_path(std::string(c.name) + ".json"));
            CgalCounts cg;
            const CheckReport r = check_round_trip(m, c, ext, &cg);
            CheckOptions opt;
            opt.require_closed = c.closed;
            INFO(c.name << ext << ": " << summary(r));
            CHECK(defect_count(r) == 0);
            CHECK(check_passed(r, opt));
            CHECK(r.closed == c.closed);
            if (c.closed) {
                REQUIRE(r.components.size() == 1);
                CHECK(r.components[0].closed);
                CHECK(r.components[0].euler == c.euler);
                CHECK(r.components[0].genus == (2 - c.euler) / 2);
                CHECK(r.components[0].volume.has_value());
            } else {
                CHECK(r.border_edges > 0);
            }
            // CGAL's own view agrees.
            CHECK(cg.built);
            CHECK(cg.duplicated_points == 0);
            CHECK(cg.closed == r.closed);
            CHECK(cg.border_halfedges == r.border_edges);
        }
}

TEST_CASE("teapot and teacup pass: the handles are shells touching the body",
          "[check][bundled][heavy]") {
    // shared/models/README.md: one handle end is a body corner (one welded
    // vertex where the handle's and the body's shells touch: a shell contact),
    // the other end (the teapot: both) pokes into the body. Shells touch only
    // through edges, so the handle is a shell of its own like the spout and its
    // crossings are overlaps, not self-intersections.
    struct Handle {
        const char* name;
        Vec3 touch;
        size_t components;
        int border_edges;
    };
    for (const Handle& h : {Handle{"teapot", {-2, 0, 0.9}, 4, 208},
                            Handle{"teacup", {-0.454545, 0.772727, 0}, 2, 128}})
        for (const std::string ext : {".glb", ".off"}) {
            const Model m = load_model(test::model_path(std::string(h.name) + ".json"));
            CgalCounts cg;
            const CheckReport r = check_round_trip(m, {h.name}, ext, &cg);
            INFO(h.name << ext << ": " << summary(r));
            CHECK(defect_count(r) == 0);
            CHECK(check_passed(r, {}));
            CHECK(r.non_manifold_vertices.empty());
            CHECK(r.self_intersections.empty());
            REQUIRE(r.shell_contacts.size() == 1);
            if (ext == ".off") CHECK(r.shell_contacts[0].position == h.touch);
            CHECK(distance(r.shell_contacts[0].position, h.touch) < 1e-6);
            CHECK(!r.overlaps.empty());
            CHECK(r.components.size() == h.components);
            CHECK(r.border_edges == h.border_edges);
            // CGAL splits the touching vertex and agrees on the borders.
            CHECK(cg.built);
            CHECK(cg.duplicated_points == 1);
            CHECK(cg.closed == r.closed);
            CHECK(cg.border_halfedges == r.border_edges);
        }
    // The handle (teapot: surfaces 12-15, teacup: 12-13) is one shell of its
    // own; its crossings with the body (4-11) are overlaps, as are the teapot
    // spout's (16-19), and nothing else overlaps.
    for (const auto& [name, last] : {std::pair{"teapot", 15}, std::pair{"teacup", 13}}) {
        const Model m = load_model(test::model_path(std::string(name) + ".json"));
        const Tessellation t = tessellate(m, {});
        const CheckReport r = check_mesh(t.mesh, {});
        INFO(name);
        auto surface = [&](int tri) { return t.mesh.triangle_surface[tri]; };
        // A copy: clang 14 cannot capture a structured binding in a lambda.
        const int last_handle = last;
        auto handle = [&](int tri) { return surface(tri) >= 12 && surface(tri) <= last_handle; };
        std::set<int> handle_shells, other_shells;
        for (int tri = 0; tri < t.mesh.triangle_count(); ++tri)
            (handle(tri) ? handle_shells : other_shells).insert(r.triangle_component[tri]);
        CHECK(handle_shells.size() == 1);
        CHECK(other_shells.count(*handle_shells.begin()) == 0);
        int handle_overlaps = 0;
        for (const TrianglePair& p : r.overlaps) {
            int a = surface(p.t0), b = surface(p.t1);
            if (a > b) std::swap(a, b);
            CHECK(a >= 4);
            CHECK(a <= 11);
            CHECK(b >= 12);
            CHECK(b <= (std::string(name) == "teapot" ? 19 : last));
            handle_overlaps += handle(p.t0) || handle(p.t1);
        }
        CHECK(handle_overlaps > 0);
    }
}

TEST_CASE("teaspoon: its nearly pinched ends are border loops; the folded handle end "
          "shows at finer tolerances",
          "[check][bundled]") {
    // shared/models/README.md: bowl tip (patches 0-3 u0) and handle end (12-15
    // u1) are free boundaries around tiny sliver holes. docs/check.md explains.
    const Model m = load_model(test::model_path("teaspoon.json"));
    for (const std::string ext : {".glb", ".off"}) {
        CgalCounts cg;
        const CheckReport r = check_round_trip(m, {"teaspoon"}, ext, &cg);
        INFO("teaspoon" << ext << ": " << summary(r));
        CHECK(defect_count(r) == 0);
        CHECK(r.components.size() == 1);
        CHECK_FALSE(r.closed);
        REQUIRE(r.border_loops.size() == 2);
        // Bowl tip: 22 edges around a 0.085 long sliver at y ~ 0.2; handle end:
        // 6 edges, 0.037 long, at y = -1.
        std::vector<BorderLoop> loops = r.border_loops;
        std::sort(loops.begin(), loops.end(),
                  [](const BorderLoop& a, const BorderLoop& b) { return a.edges > b.edges; });
        CHECK(loops[0].edges == 22);
        CHECK(loops[0].length == Approx(0.08496).epsilon(1e-3));
        CHECK(loops[0].start.y > 0.19);
        CHECK(loops[1].edges == 6);
        CHECK(loops[1].length == Approx(0.03679).epsilon(1e-3));
        CHECK(loops[1].start.y == Approx(-1));
        CHECK(r.border_edges == 28);
        CHECK(cg.built);
        CHECK(cg.duplicated_points == 0);
        CHECK(cg.closed == r.closed);
        CHECK(cg.border_halfedges == r.border_edges);
    }

    // 20x finer: the handle end's boundary curve 12.u1 is a straight line
    // traversed forth and back (control points x = -3.57e-4, 3.57e-4, 0, 0 at
    // y = -1, z = 0.0178571: x runs up to 8.93e-5 at t = 1/2 and back to 0).
    // Once it is split at t = 1/2 its two chords overlap: the corner (0, -1,
    // 0.0178571) lies inside the first chord (a T-junction at distance 0) and
    // patch 12's triangles along it fold onto each other; the chords are a seam
    // crack of the surface with itself. The exact surface
    // does the same; it is the data, not the tessellation.
    TessellationOptions opt;
    opt.eps1 = 0.05 * 0.001 * d_max(m);
    opt.eps2 = 0.05 * 0.02 * d_max(m);
    const Tessellation t = tessellate(m, opt);
    const CheckReport r = check_mesh(t.mesh, {});
    INFO(summary(r));
    const Vec3 corner{0, -1, 0.0178571};
    REQUIRE(r.t_junctions.size() == 1);
    CHECK(r.t_junctions[0].position == corner);
    CHECK(r.t_junctions[0].distance < 1e-15);
    CHECK(t.mesh.triangle_surface[r.t_junctions[0].triangle] == 12);
    REQUIRE(!r.self_intersections.empty());
    for (const TrianglePair& p : r.self_intersections) {
        CHECK(t.mesh.triangle_surface[p.t0] == 12);
        CHECK(t.mesh.triangle_surface[p.t1] == 12);
        CHECK(distance(p.location, corner) < 1e-3);
    }
    // The two overlapping chords are border edges running along each other: one
    // seam of crack edges at the corner, as short as the fold.
    REQUIRE(r.seams.size() == 1);
    CHECK(distance(r.seams[0].location, corner) < 1e-3);
    CHECK(r.seams[0].length < 1e-3);
    for (const Crack& c : r.cracks) CHECK(distance(c.location, corner) < 1e-3);
    CHECK(defect_count(r) == 1 + static_cast<int>(r.cracks.size() + r.self_intersections.size()));
    CHECK(r.non_manifold_edges.empty());
    CHECK(r.non_manifold_vertices.empty());
    CHECK(r.degenerate_triangles.empty());
    CHECK(r.border_loops.size() == 2);
}
