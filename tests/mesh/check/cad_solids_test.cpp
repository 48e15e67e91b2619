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
#include <seamless/tessellate/trimmed/brep_tessellation.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

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

namespace {

// trj3_s1-ct's self-intersecting pairs, by where they lie: on HEAD_BACK's
// face #1905 (the B-rep's), on a face with an edge whose tolerance exceeds
// D, or elsewhere.
struct Trj3Intersections {
    int on_1905 = 0, tolerant_face = 0, elsewhere = 0;
};

// Largest edge tolerance per face.
std::vector<double> face_tolerances(const BRep& b) {
    std::vector<double> out(b.faces.size(), 0);
    for (size_t f = 0; f < b.faces.size(); ++f)
        for (const BRepLoop& loop : b.faces[f].loops)
            for (const BRepCoedge& c : loop.coedges)
                out[f] = std::max(out[f], b.edges[c.edge].tolerance);
    return out;
}

Trj3Intersections trj3_intersections() {
    // As `seamless tessellate` meshes it: each part once, placed, D that of
    // the model placed.
    ModelLoadOptions load;
    load.keep_assembly = true;
    const Model m =
        load_model(test::shared_dir() / "models" / "cad-corpus" / "occt_trj3_s1-ct-214.stp", load);
    const Model placed = flatten_assembly(m);
    TessellationOptions o;
    o.patch_trees = false;
    o.tolerance = brep_deviation(placed, o);
    const TriangleMesh mesh = placed_mesh(tessellate(m, o).mesh, m);
    CheckOptions co;
    co.require_closed = true;
    const CheckReport r = check_mesh(mesh, co);
    for (const auto& c : r.components) CHECK(c.closed);
    CHECK(defect_count(r) == static_cast<int>(r.self_intersections.size()));
    const std::vector<double> tolerance = face_tolerances(placed.brep);
    Trj3Intersections out;
    for (const TrianglePair& p : r.self_intersections) {
        const int a = mesh.triangle_face[p.t0], b = mesh.triangle_face[p.t1];
        if (placed.brep.faces[a].name == "#1905" || placed.brep.faces[b].name == "#1905")
            ++out.on_1905;
        else if (std::max(tolerance[a], tolerance[b]) > o.tolerance)
            ++out.tolerant_face;
        else
            ++out.elsewhere;
    }
    return out;
}

} // namespace

TEST_CASE("CAD assemblies: trj3_s1-ct's solids are closed, and self-intersect where the B-rep "
          "does",
          "[heavy][cad][solids]") {
    // HEAD_BACK's face #1905 lies on the sphere of radius 60 that its faces
    // #1951, #1985 and #2011 lie on, and its loop bounds three quarters of
    // it (34,450 of 45,239 mm^2), over them and across the plane #1826 and
    // the faces #2181 and #2219 inside the sphere: OpenCASCADE's
    // BOPAlgo_ArgumentAnalyzer finds HEAD_BACK self-intersecting at #1905
    // (docs/results/cad.md). Its mesh crosses itself there as the B-rep
    // does, and elsewhere only on the main body's walls, 1.0 apart, where a
    // face with an edge of tolerance 0.6 to 0.76 (D = 0.52) had its interior
    // allowed D plus that tolerance.
    const Trj3Intersections x = trj3_intersections();
    CHECK(x.on_1905 > 0);
    CHECK(x.elsewhere == 0);
}

// The walls' faces have edges of tolerance 0.6 to 0.76 (D = 0.52): held to
// D plus that tolerance, their interiors sagged through the wall's other
// side; held to what their edges' measured offsets force, they do not.
TEST_CASE("CAD assemblies: trj3_s1-ct's main body walls do not cross", "[heavy][cad][solids]") {
    CHECK(trj3_intersections().tolerant_face == 0);
}
