// SPDX-License-Identifier: MIT
// Surfaces whose normals disagree (as IGES files' surfaces do) come out of the
// tessellation consistently oriented, and closed models face outward.
#include <tessellate/mesh_properties.h>
#include <tessellate/seam_cases.h>

#include <seamless/tessellate/seams/surface_orientation.h>
#include <seamless/tessellate/tessellation.h>

#include <catch2/catch.hpp>

using namespace seamless;
using namespace seamless::test;

namespace {

double signed_volume(const TriangleMesh& m) {
    double v = 0;
    for (const auto& t : m.triangles)
        v += dot(m.positions[t[0]], cross(m.positions[t[1]], m.positions[t[2]])) / 6;
    return v;
}

struct Oriented {
    MeshReport report;
    double volume;
    int flipped;
};

Oriented tessellate_box(const std::vector<int>& reversed, bool orient) {
    std::vector<BSplineSurface> f = bulged_box_faces();
    for (int i : reversed) f[i] = reverse(f[i], 0);
    TessellationOptions o;
    o.orient_surfaces = orient;
    const Tessellation t = tessellate(model_of(f, "box"), o);
    return {analyse_mesh(t.mesh, t.stats.d_max), signed_volume(t.mesh), t.stats.flipped_surfaces};
}

} // namespace

TEST_CASE("surface orientation: faces reversed against their neighbours are flipped back",
          "[tessellate][orientation][heavy]") {
    const Oriented raw = tessellate_box({1, 3}, false);
    CHECK(raw.report.misoriented_edges > 0);
    const Oriented fixed = tessellate_box({1, 3}, true);
    CHECK(fixed.report.misoriented_edges == 0);
    CHECK(fixed.report.border_edges == 0);
    CHECK(fixed.report.euler() == 2);
    CHECK(fixed.flipped == 2);
    CHECK(fixed.volume > 0);
}

TEST_CASE("surface orientation: a closed model facing inward is turned outward",
          "[tessellate][orientation][heavy]") {
    const Oriented raw = tessellate_box({0, 1, 2, 3, 4, 5}, false);
    CHECK(raw.report.misoriented_edges == 0);
    CHECK(raw.volume < 0);
    const Oriented fixed = tessellate_box({0, 1, 2, 3, 4, 5}, true);
    CHECK(fixed.flipped == 6);
    CHECK(fixed.volume == Approx(-raw.volume).epsilon(1e-12));
    CHECK(fixed.report.misoriented_edges == 0);
}

TEST_CASE("surface orientation: a consistent outward model is left alone",
          "[tessellate][orientation]") {
    const Oriented fixed = tessellate_box({}, true);
    CHECK(fixed.flipped == 0);
    CHECK(fixed.volume > 0);
}

TEST_CASE("surface orientation: flipped triangles keep corner normals and uvs with their corners",
          "[tessellate][orientation]") {
    std::vector<BSplineSurface> f = bulged_box_faces();
    f[2] = reverse(f[2], 0);
    const Tessellation t = tessellate(model_of(f, "box"));
    REQUIRE(t.stats.flipped_surfaces == 1);
    // Every corner normal points to the side the triangle's winding gives it.
    int disagree = 0;
    for (size_t i = 0; i < t.mesh.triangles.size(); ++i) {
        const auto& tri = t.mesh.triangles[i];
        const Vec3 n = cross(t.mesh.positions[tri[1]] - t.mesh.positions[tri[0]],
                             t.mesh.positions[tri[2]] - t.mesh.positions[tri[0]]);
        for (const Vec3& c : t.mesh.corner_normals[i])
            if (dot(n, c) <= 0) ++disagree;
    }
    CHECK(disagree == 0);
}

TEST_CASE("surface orientation: the same flips for any thread count", "[tessellate][orientation]") {
    // Faces reversed, and an open box (a face left out: its rim edges used once).
    for (bool open : {false, true}) {
        std::vector<BSplineSurface> f = bulged_box_faces();
        f[1] = reverse(f[1], 0);
        f[4] = reverse(f[4], 0);
        if (open) f.pop_back();
        TessellationOptions o;
        o.orient_surfaces = false;
        const Tessellation t = tessellate(model_of(f, "box"), o);
        TriangleMesh one = t.mesh;
        const OrientationResult r1 = orient_surfaces(one, 1);
        CHECK(r1.flipped_surfaces > 0);
        for (int threads : {2, 3}) {
            TriangleMesh m = t.mesh;
            const OrientationResult r = orient_surfaces(m, threads);
            CHECK(r.flipped_surfaces == r1.flipped_surfaces);
            CHECK(r.conflicts == r1.conflicts);
            CHECK(m.triangles == one.triangles);
        }
    }
}
