// SPDX-License-Identifier: MIT
// Assemblies and multi-solid parts as their placed meshes (what a PLY from
// `seamless tessellate` holds): each solid judged apart comes out closed with
// no defect, and where solids touch, as the file places them, is reported as
// contacts; judged whole, the same mesh fails (docs/check.md).
#include "test_util.h"

#include <seamless/mesh/check/check.h>
#include <seamless/mesh/io/placed_mesh.h>
#include <seamless/model/model.h>
#include <seamless/tessellate/tessellation.h>

#include <catch2/catch.hpp>

#include <set>
#include <string>

using namespace seamless;

namespace {

void check_solids(const std::filesystem::path& file, int solids) {
    INFO(file.string());
    const Model m = load_model(file);
    TessellationOptions o;
    o.patch_trees = false;
    const TriangleMesh mesh = placed_mesh(tessellate(m, o).mesh, m);
    REQUIRE(mesh.triangle_solid.size() == mesh.triangles.size());
    CHECK(std::set<int>(mesh.triangle_solid.begin(), mesh.triangle_solid.end()).size() ==
          static_cast<size_t>(solids));
    CheckOptions co;
    co.require_closed = true;
    const CheckReport r = check_mesh(mesh, co);
    CHECK(r.bodies == CheckBodies::solids);
    CHECK(r.body_count == solids);
    INFO(defect_count(r) << " defects");
    CHECK(check_passed(r, co));
    CHECK(r.components.size() == static_cast<size_t>(solids));
    CHECK_FALSE(r.body_contacts.empty());
    for (const BodyContact& c : r.body_contacts) {
        CHECK(c.body0 < c.body1);
        CHECK(c.triangle_pairs > 0);
    }
    co.by_solid = false;
    const CheckReport whole = check_mesh(mesh, co);
    CHECK(whole.bodies == CheckBodies::whole);
    CHECK_FALSE(check_passed(whole, co));
}

} // namespace

TEST_CASE("CAD assemblies: as1's 18 placed solids pass one by one, touching where placed",
          "[heavy][cad][solids]") {
    check_solids(test::data_dir() / "models" / "cad" / "occt_as1-oc-214-mat.stp", 18);
}

TEST_CASE("CAD assemblies: bug33398's four solids sharing edges pass one by one",
          "[heavy][cad][solids]") {
    check_solids(test::shared_dir() / "models" / "cad-corpus" / "occt_bug33398.step", 4);
}
