// SPDX-License-Identifier: MIT
// The intensity of a certified cluster as second-order jets (intensity_jets of
// second_order.h, from surface_jets.h and interval_jet2.h): over every
// certified cluster, each finite partial encloses the partial of the exact
// intensity at points inside the cluster (central differences, their
// truncation estimated by halving the step). Scenes: the teapot under its own
// light, under a light at the eye (highlights facing the viewer), under a
// grazing light (the diffuse term's terminator crosses clusters), with no light
// reaching it (a shadowed cluster: only ambient), and a rational cylinder.
#include "render/clusters/cluster_samples.h"
#include "render/scene_fixtures.h"
#include "test_util.h"

#include <seamless/render/clusters/second_order.h>
#include <seamless/render/pixels/pixel_solve.h>
#include <seamless/render/scene/projection.h>
#include <seamless/render/subscreen/primary_cluster.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

using namespace seamless;

namespace {

struct JetTally {
    long long clusters = 0, samples = 0, checked_first = 0, checked_second = 0, misses = 0;
    long long point_checked = 0, point_misses = 0; // jets of single rays (second partials)
    long long kinks = 0;      // channels whose second partials are entire (not C^2 over B)
    long long highlights = 0; // samples where the specular term dominates the blue channel
};

// Value and partials I, I_a, I_b, I_aa, I_ab, I_bb of the exact intensity at
// (a, b) per channel, by central differences with steps ha, hb.
using Partials = std::array<std::array<double, 6>, 3>;
bool differences(const Scene& lighting, const ProjectedPatch& pp, const ParamBox& box, double a,
                 double b, double ha, double hb, Partials& d) {
    std::array<double, 3> f[3][3];
    for (int i = -1; i <= 1; ++i)
        for (int j = -1; j <= 1; ++j)
            if (!test::exact_intensity(lighting, pp, box, a + i * ha, b + j * hb, f[i + 1][j + 1]))
                return false;
    for (int c = 0; c < 3; ++c) {
        auto F = [&](int i, int j) { return f[i + 1][j + 1][c]; };
        d[c] = {F(0, 0),
                (F(1, 0) - F(-1, 0)) / (2 * ha),
                (F(0, 1) - F(0, -1)) / (2 * hb),
                (F(1, 0) - 2 * F(0, 0) + F(-1, 0)) / (ha * ha),
                (F(1, 1) - F(1, -1) - F(-1, 1) + F(-1, -1)) / (4 * ha * hb),
                (F(0, 1) - 2 * F(0, 0) + F(0, -1)) / (hb * hb)};
    }
    return true;
}

// The finite partials of jets I that miss the differences d2 (step h / 2) by
// more than their truncation, estimated from d1 (step h) by Richardson: a
// central difference is off by about a third of its change on halving the
// step. The value is exact. Counts the partials checked. Only where `over`
// (jets over a region holding the differences' stencils) is finite, and with
// `smooth`, only channels that `over` proves C^2: differences across a kink
// need not match the derivative at the sample.
int misses(const std::array<IntervalJet2, 3>& I, const Partials& d1, const Partials& d2,
           JetTally& tally, const std::array<IntervalJet2, 3>& over, bool smooth) {
    int n = 0;
    for (int c = 0; c < 3; ++c) {
        const Interval got[6] = {I[c].v, I[c].da, I[c].db, I[c].daa, I[c].dab, I[c].dbb};
        const Interval region[6] = {over[c].v,   over[c].da,  over[c].db,
                                    over[c].daa, over[c].dab, over[c].dbb};
        if (smooth && !(region[3].is_finite() && region[4].is_finite() && region[5].is_finite()))
            continue;
        for (int k = 0; k < 6; ++k) {
            if (!got[k].is_finite() || !region[k].is_finite()) continue;
            const double tol =
                k == 0 ? 1e-12 : std::abs(d1[c][k] - d2[c][k]) + 1e-7 * (1 + std::abs(d2[c][k]));
            const bool ok = got[k].lo() - tol <= d2[c][k] && d2[c][k] <= got[k].hi() + tol;
            n += !ok;
            if (!ok)
                UNSCOPED_INFO("channel " << c << " partial " << k << ": " << got[k] << " misses "
                                         << d2[c][k] << " (tolerance " << tol << ")");
            tally.checked_first += k == 1 || k == 2;
            tally.checked_second += k >= 3;
        }
    }
    return n;
}

// Every block x block sub-screen of a w x h image against every patch whose
// box the cluster certificate contracts, with the lights of `lighting`.
JetTally check_jets(const ProjectedScene& ps, const Scene& lighting, int w, int h, int block) {
    JetTally tally;
    ClusterSystem sys;
    for (int y0 = 0; y0 + block <= h; y0 += block)
        for (int x0 = 0; x0 + block <= w; x0 += block) {
            const double ca[2] = {ps.frame.screen_a(x0 + 0.5), ps.frame.screen_a(x0 + block - 0.5)};
            const double cb[2] = {ps.frame.screen_b(y0 + 0.5), ps.frame.screen_b(y0 + block - 0.5)};
            const Interval a = Interval::hull(ca[0], ca[1]), b = Interval::hull(cb[0], cb[1]);
            for (const ProjectedPatch& pp : ps.patches) {
                ParamBox box;
                if (!test::certified_cluster(pp, a, b, sys, box)) continue;
                ++tally.clusters;
                const Material& mat = lighting.materials[pp.material];
                const PatchEnclosure e = enclose(pp.forms, box);
                const std::array<IntervalJet2, 3> I = intensity_jets(
                    {pp, box, e, sys}, {lighting, mat}, mark_jacobian(sys, box).A, a, b);
                for (int c = 0; c < 3; ++c) tally.kinks += !I[c].daa.is_finite();
                // Steps of 1/16 of B (truncation ~ h^2 I'''' / 12), halved for
                // the estimate of the truncation; samples at least 1/8 inside B.
                const double ha = (ca[1] - ca[0]) / 16, hb = (cb[1] - cb[0]) / 16;
                for (const double u : {0.125, 0.5, 0.875})
                    for (const double v : {0.125, 0.5, 0.875}) {
                        const double sa = ca[0] + u * (ca[1] - ca[0]);
                        const double sb = cb[0] + v * (cb[1] - cb[0]);
                        Partials d1, d2;
                        REQUIRE(differences(lighting, pp, box, sa, sb, ha, hb, d1));
                        REQUIRE(differences(lighting, pp, box, sa, sb, ha / 2, hb / 2, d2));
                        ++tally.samples;
                        tally.highlights += d2[2][0] > 0.35;
                        tally.misses += misses(I, d1, d2, tally, I, false);
                        // The jets of the single ray through the sample (a
                        // cluster 2e-9 wide): nearly thin, so they check the
                        // formulas themselves, which the wide jets above
                        // could hide (a wrong term in I_ab, say).
                        if (u != 0.5 || v != 0.5) continue;
                        const Interval pa(sa - 1e-9, sa + 1e-9), pb(sb - 1e-9, sb + 1e-9);
                        ClusterSystem psys;
                        ParamBox pbox;
                        if (!test::certified_cluster(pp, pa, pb, psys, pbox)) continue;
                        const PatchEnclosure pe = enclose(pp.forms, pbox);
                        const std::array<IntervalJet2, 3> J =
                            intensity_jets({pp, pbox, pe, psys}, {lighting, mat},
                                           mark_jacobian(psys, pbox).A, pa, pb);
                        JetTally point;
                        tally.point_misses += misses(J, d1, d2, point, I, true);
                        tally.point_checked += point.checked_second;
                    }
            }
        }
    return tally;
}

// The teapot at 320 x 240 in 8 x 8 clusters, under its own light (light
// 0), one light at `position` (1), or none (2).
JetTally teapot_jets(int light, Vec3 position = {}) {
    const ProjectedScene ps =
        project_scene(load_scene(test::data_dir() / "scenes" / "teapot.json"), 320, 240);
    Scene lit = ps.lighting;
    if (light == 1) {
        lit.lights.resize(1);
        lit.lights[0].position = position;
    } else if (light == 2) {
        lit.lights.clear();
    }
    return check_jets(ps, lit, 320, 240, 8);
}

// What every scene must show: no miss, and single rays checked.
void check_common(const JetTally& t) {
    INFO("clusters " << t.clusters << ", samples " << t.samples << ", second partials checked "
                     << t.checked_second << " (single rays " << t.point_checked << "), kinks "
                     << t.kinks << ", highlights " << t.highlights);
    CHECK(t.misses == 0);
    CHECK(t.point_misses == 0);
    CHECK(t.point_checked > 100);
}

std::string read_text(const std::filesystem::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

} // namespace

TEST_CASE("Intensity jets hold the sampled partials: teapot under its own light",
          "[second_order][heavy]") {
    const JetTally t = teapot_jets(0);
    check_common(t);
    CHECK(t.checked_second > 5000);
}

TEST_CASE("Intensity jets hold the sampled partials: highlights", "[second_order][heavy]") {
    // A light beside the eye: highlights face the viewer.
    const JetTally t = teapot_jets(1, {0.05, -0.05, 0.0});
    check_common(t);
    CHECK(t.highlights > 20);
    CHECK(t.checked_second > 5000);
}

TEST_CASE("Intensity jets hold the sampled partials: grazing light", "[second_order][heavy]") {
    // Far to the side at the teapot's depth (about 9 in camera coordinates):
    // the diffuse term's terminator runs down the teapot's visible side.
    const JetTally t = teapot_jets(1, {1000.0, 0.0, 9.0});
    check_common(t);
    CHECK(t.kinks > 0);
    CHECK(t.checked_second > 2000);
}

TEST_CASE("Intensity jets of a shadowed cluster are constant", "[second_order][heavy]") {
    // No light: what SHADE passes when no light reaches the cluster.
    const JetTally t = teapot_jets(2);
    check_common(t);
    CHECK(t.kinks == 0);
    CHECK(t.checked_second > 1000);
}

TEST_CASE("Intensity jets hold the sampled partials: a rational cylinder",
          "[second_order][heavy]") {
    const auto dir = test::scratch_dir("intensity-jets-cylinder");
    const Scene scene =
        test::one_model_scene(dir, read_text(test::model_path("quarter_cylinder.json")),
                              {3.0, 2.5, 1.2}, {0.5, 0.5, 1.0});
    const ProjectedScene ps = project_scene(scene, 256, 192);
    REQUIRE(ps.patches.front().forms.rational);
    Scene lit = ps.lighting; // a darker material than the fixture's, which saturates
    lit.materials[0].color = {0.5, 0.4, 0.3};
    lit.materials[0].diffuse = 0.6;
    lit.materials[0].specular = 0.2;
    const JetTally t = check_jets(ps, lit, 256, 192, 8);
    check_common(t);
    CHECK(t.checked_second > 5000);
}
