// SPDX-License-Identifier: MIT
// Stiff cases: huge and tiny coordinates, and a model far from the origin.
// Scaling by a power of two is exact, so the tessellation must be the same
// mesh scaled (same counts, positions scaled bit for bit), crack-free; the
// interval enclosures must still contain sampled points (no overflow or
// underflow lets a value escape); a translated model stays crack-free.
#include "mesh_properties.h"
#include "seam_cases.h"
#include "test_util.h"

#include <seamless/model/model.h>
#include <seamless/spline/enclosure/enclosure.h>
#include <seamless/tessellate/tessellation.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

using namespace seamless;

namespace {

Model transformed(const Model& m, double scale, Vec3 offset) {
    Model r = m;
    for (BSplineSurface& s : r.surfaces)
        for (Vec3& p : s.points) p = scale * p + offset;
    return r;
}

} // namespace

TEST_CASE("Huge and tiny coordinates tessellate to the same mesh, scaled", "[stiff][heavy]") {
    const Model teapot = load_model(test::model_path("teapot.json"));
    const Tessellation base = tessellate(teapot);
    for (int e : {-500, 500}) {
        const double scale = std::ldexp(1.0, e);
        INFO("scale 2^" << e);
        const Model m = transformed(teapot, scale, {});
        const Tessellation t = tessellate(m);
        REQUIRE(t.mesh.vertex_count() == base.mesh.vertex_count());
        REQUIRE(t.mesh.triangle_count() == base.mesh.triangle_count());
        CHECK(t.mesh.triangles == base.mesh.triangles);
        bool exact = true;
        for (int v = 0; v < t.mesh.vertex_count(); ++v)
            exact &= t.mesh.positions[v] == scale * base.mesh.positions[v];
        CHECK(exact);
        // The subpatches too (scaled back by the fans, write_fans).
        REQUIRE(t.subpatches.size() == base.subpatches.size());
        bool same_subpatches = true;
        for (size_t i = 0; i < t.subpatches.size(); ++i) {
            const Subpatch &p = t.subpatches[i], &q = base.subpatches[i];
            same_subpatches &= p.rect == q.rect && p.centre == scale * q.centre &&
                               p.fan_error == scale * q.fan_error &&
                               p.error_bound == scale * q.error_bound;
            for (int k = 0; k < 4; ++k) same_subpatches &= p.corners[k] == scale * q.corners[k];
        }
        CHECK(same_subpatches);
        CHECK(t.stats.max_error_bound == Approx(scale * base.stats.max_error_bound).epsilon(1e-9));
        const test::MeshReport r = test::analyse_mesh(t.mesh, t.stats.d_max, false);
        CHECK(r.duplicate_positions == 0);
        // (The helper's area test squares coordinates: at 2^-500 that underflows,
        // so zero area is judged on the exactly scaled positions above instead.)
        if (e > 0) CHECK(r.zero_area == 0);
        CHECK(r.nonmanifold_edges == 0);
        CHECK(r.misoriented_edges == 0);
    }
}

TEST_CASE("Enclosures hold sampled points at huge and tiny scales", "[stiff][heavy]") {
    const Model teapot = load_model(test::model_path("teapot.json"));
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    for (int e : {-500, 500}) {
        const double scale = std::ldexp(1.0, e);
        INFO("scale 2^" << e);
        for (const BezierPatch& b : bezier_patches(transformed(teapot, scale, {}))) {
            const PatchForms f = patch_forms(b);
            for (int k = 0; k < 20; ++k) {
                const double s0 = U(rng), t0 = U(rng), w = std::ldexp(U(rng), -(k % 10) * 4);
                const ParamBox box{Interval(s0, std::min(1.0, s0 + w)),
                                   Interval(t0, std::min(1.0, t0 + w))};
                const PatchEnclosure enc = enclose(f, box);
                for (int n = 0; n < 50; ++n) {
                    const double s = box.s.lo() + U(rng) * (box.s.hi() - box.s.lo());
                    const double t = box.t.lo() + U(rng) * (box.t.hi() - box.t.lo());
                    const SurfacePoint p = evaluate(b, s, t);
                    for (int i = 0; i < 3; ++i) {
                        CHECK(enc.point[i].contains(p.point[i]));
                        CHECK(std::isfinite(enc.point[i].width()));
                    }
                }
            }
        }
    }
}

TEST_CASE("A model far from the origin stays crack-free", "[stiff][heavy]") {
    const Model m = transformed(load_model(test::model_path("torus.json")), 1.0, {1e6, -2e6, 3e6});
    const Tessellation t = tessellate(m);
    const test::MeshReport r = test::analyse_mesh(t.mesh, t.stats.d_max, false);
    CHECK(r.duplicate_positions == 0);
    CHECK(r.border_edges == 0);
    CHECK(r.nonmanifold_edges == 0);
    CHECK(r.misoriented_edges == 0);
    CHECK(r.euler() == 0);
}

TEST_CASE("Seams matched by geometry scale exactly and survive far from the origin",
          "[stiff][heavy]") {
    // The closed seam case with every mismatch at once (seam_cases.h).
    const std::vector<test::SeamCase> cases = test::closed_seam_cases();
    const auto it = std::find_if(cases.begin(), cases.end(), [](const test::SeamCase& c) {
        return c.name == "everything at once";
    });
    REQUIRE(it != cases.end());
    const Tessellation base = tessellate(it->model);
    REQUIRE(base.stats.seam_vertices > 0);
    for (int e : {-500, 500}) {
        const double scale = std::ldexp(1.0, e);
        INFO("scale 2^" << e);
        const Tessellation t = tessellate(transformed(it->model, scale, {}));
        CHECK(t.mesh.triangles == base.mesh.triangles);
        bool exact = t.mesh.vertex_count() == base.mesh.vertex_count();
        for (int v = 0; exact && v < t.mesh.vertex_count(); ++v)
            exact = t.mesh.positions[v] == scale * base.mesh.positions[v];
        CHECK(exact);
    }
    const Model far = transformed(it->model, 1.0, {1e6, -2e6, 3e6});
    const Tessellation t = tessellate(far);
    const test::MeshReport r = test::analyse_mesh(t.mesh, t.stats.d_max, false);
    CHECK(r.border_edges == 0);
    CHECK(r.nonmanifold_edges == 0);
    CHECK(r.misoriented_edges == 0);
    CHECK(r.euler() == 2);
    CHECK(test::count_shells(t.mesh) == 1);
}
