// SPDX-License-Identifier: MIT
// STEP and IGES files with trimmed faces read as B-reps (lib/model/step_iges/
// brep_reader.h): the conventions of model/brep.h hold on real files of the
// CAD corpus (loops closed in (u, v) and in 3D, pcurves within their edge's
// tolerance of the 3D curve, every edge of a closed shell used twice), the
// files seamless refused before issue 28 load, and hostile files are still
// refused.
#include "test_util.h"

#include <seamless/base/error.h>
#include <seamless/model/model.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <string>

using namespace seamless;

namespace {

std::filesystem::path corpus(const std::string& name) {
    return test::shared_dir() / "models" / "cad-corpus" / name;
}

// Largest |S(pcurve(t)) - curve(t)| over samples of the coedge, divided by
// the edge's tolerance.
double relative_gap(const Model& m, const BRepFace& f, const BRepCoedge& c) {
    const BRepEdge& e = m.brep.edges[c.edge];
    double worst = 0;
    for (int k = 0; k <= 32; ++k) {
        const double t = e.t0 + (e.t1 - e.t0) * k / 32;
        const Vec3 uv = evaluate(m.brep.pcurves[c.pcurve], t).point;
        const Vec3 p = evaluate(m.surfaces[f.surface], uv.x, uv.y).point;
        const Vec3 q = e.degenerate() ? m.brep.vertices[e.start].point
                                      : evaluate(m.brep.curves[e.curve], t).point;
        worst = std::max(worst, distance(p, q) / e.tolerance);
    }
    return worst;
}

Vec3 coedge_end(const Model& m, const BRepCoedge& c, bool start) {
    const BRepEdge& e = m.brep.edges[c.edge];
    return evaluate(m.brep.pcurves[c.pcurve], (start != c.reversed) ? e.t0 : e.t1).point;
}

// The conventions of model/brep.h, checked on what the reader produced.
void check_brep(const Model& m) {
    const BRep& b = m.brep;
    REQUIRE_FALSE(b.empty());
    REQUIRE(m.surfaces.size() == b.faces.size());
    REQUIRE(m.origins.size() == m.surfaces.size());
    double worst_gap = 0;
    for (const BRepFace& f : b.faces) {
        INFO(f.name);
        REQUIRE_FALSE(f.loops.empty());
        const BSplineSurface& s = m.surfaces[f.surface];
        for (const BRepLoop& loop : f.loops) {
            REQUIRE_FALSE(loop.coedges.empty());
            for (size_t i = 0; i < loop.coedges.size(); ++i) {
                const BRepCoedge& c = loop.coedges[i];
                const BRepCoedge& next = loop.coedges[(i + 1) % loop.coedges.size()];
                const BRepEdge& e = b.edges[c.edge];
                REQUIRE(e.t0 < e.t1);
                worst_gap = std::max(worst_gap, relative_gap(m, f, c));
                // Consecutive coedges meet at a vertex, in 3D and on the surface.
                const BRepEdge& en = b.edges[next.edge];
                CHECK((c.reversed ? e.start : e.end) == (next.reversed ? en.end : en.start));
                const Vec3 a = coedge_end(m, c, false), z = coedge_end(m, next, true);
                const double joint =
                    distance(evaluate(s, a.x, a.y).point, evaluate(s, z.x, z.y).point);
                CHECK(joint <= 2 * (e.tolerance + en.tolerance));
            }
        }
    }
    // Within the tolerance, with the slack of sampling between the reader's
    // own samples.
    CHECK(worst_gap <= 1.01);
    for (const BRepShell& shell : b.shells) {
        std::map<int, int> uses;
        for (int f : shell.faces)
            for (const BRepLoop& loop : b.faces[f].loops)
                for (const BRepCoedge& c : loop.coedges)
                    if (!b.edges[c.edge].degenerate()) ++uses[c.edge];
        const bool twice =
            std::all_of(uses.begin(), uses.end(), [](auto& u) { return u.second == 2; });
        CHECK(shell.closed == twice);
    }
}

} // namespace

TEST_CASE("a cylinder: three faces, a closed shell, the side's seam used twice by it",
          "[model][cad][heavy]") {
    const Model m = load_model(test::model_path("cad/generated/cylinder.step"));
    check_brep(m);
    REQUIRE(m.brep.faces.size() == 3);
    REQUIRE(m.brep.shells.size() == 1);
    CHECK(m.brep.shells[0].closed);
    for (const BRepFace& f : m.brep.faces) {
        INFO(f.name);
        CHECK(m.origins[f.surface].exact); // the rational cylinder and planes, not approximations
        std::map<int, int> uses;
        for (const BRepLoop& loop : f.loops)
            for (const BRepCoedge& c : loop.coedges) ++uses[c.edge];
        const bool side = m.origins[f.surface].kind == "cylinder";
        const auto twice =
            std::count_if(uses.begin(), uses.end(), [](auto& u) { return u.second == 2; });
        CHECK(twice == (side ? 1 : 0));
    }
}

TEST_CASE("small corpus parts load as B-reps with closed solids", "[model][cad][heavy]") {
    for (const char* name : {"occt_bug30149_comb_bug.step",
                             "pyocc_face_recognition_sample_part.stp", "ksu_sg1-c5-214.stp"}) {
        INFO(name);
        const Model m = load_model(corpus(name));
        check_brep(m);
        REQUIRE(m.brep.solids.size() == 1);
        const BRepSolid& solid = m.brep.solids[0];
        REQUIRE_FALSE(solid.shells.empty());
        CHECK(m.brep.shells[solid.shells[0]].closed);
        // Every face belongs to the solid's shells.
        size_t faces = 0;
        for (int s : solid.shells) faces += m.brep.shells[s].faces.size();
        CHECK(faces == m.brep.faces.size());
    }
}

TEST_CASE("files seamless refused before issue 28 load", "[model][cad][heavy]") {
    // An AP242 part whose annotations OpenCASCADE 7.6 cannot read, and a
    // turbine whose seam curves name one pcurve twice.
    for (const char* name : {"nist_nist_ctc_03_asme1_ap242-e2.stp", "occt_ec_turbine-A.stp"}) {
        INFO(name);
        check_brep(load_model(corpus(name)));
    }
}

TEST_CASE("the other trimmed-face options keep their behaviour", "[model][cad][heavy]") {
    const auto file = corpus("occt_bug30149_comb_bug.step");
    ModelLoadOptions o;
    o.trimmed = TrimmedFaces::refuse;
    CHECK_THROWS_AS(load_model(file, o), InputError);
    o.trimmed = TrimmedFaces::whole_surface;
    const Model whole = load_model(file, o);
    CHECK(whole.brep.empty());
    CHECK(whole.surfaces.size() == load_model(file).surfaces.size());
}
