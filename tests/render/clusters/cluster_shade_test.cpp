// SPDX-License-Identifier: MIT
// The hits' enclosures of the cluster attempt (cluster_attempt.cpp): a mark's
// subpatch restricted to a box (restrict_mark, mark.h) holds the patch's
// points over that box, in camera coordinates (subpatch_hull) and taken to
// world coordinates (ClusterShader::world_hull, cluster_shade.h), and its
// differences hold the patch's partial derivatives (subpatch_derivatives).
#include <seamless/render/clusters/cluster_shade.h>
#include <seamless/render/scene/projection.h>
#include <seamless/render/scene/scene.h>
#include <seamless/render/subscreen/mark.h>

#include <catch2/catch.hpp>

#include "test_util.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace seamless;

namespace {

// x within h, up to a rounding slack of the doubles the sample was computed in.
bool holds(Interval h, double x) {
    const double slack = 1e-12 * (1 + std::abs(x));
    return h.lo() - slack <= x && x <= h.hi() + slack;
}

} // namespace

TEST_CASE("restricted subpatches hold the patch's points in camera and world coordinates",
          "[cluster_shade][heavy]") {
    int rational = 0; // derivatives checked on rational patches (scene 1's pan and glass)
    for (const char* name : {"teapot.json", "scene1.json"}) {
        const Scene scene = load_scene(test::data_dir() / "scenes" / name);
        const ProjectedScene ps = project_scene(scene, 64, 48);
        const ClusterShader shader(ps, scene, nullptr, nullptr, 16, true);
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> U(0.0, 1.0);
        SubpatchArena arena;
        std::vector<Interval> out;
        int checked = 0, restricted = 0;
        for (size_t p = 0; p < ps.patches.size(); ++p) {
            const ProjectedPatch& pp = ps.patches[p];
            const SubpatchShape sh = pp.shape;
            arena.clear();
            const Mark whole =
                whole_patch_mark(static_cast<int>(p), pp.patch, sh, pp.forms.control_hull, arena);
            out.resize(static_cast<size_t>(sh.size()));
            for (int n = 0; n < 20; ++n) {
                // A mark over a random box (bisections of the whole patch's),
                // restricted to another random box that overlaps it.
                Mark half[2];
                bisect_mark(arena, sh, whole, n % 2, half);
                const Mark& m = half[n / 2 % 2];
                const double s0 = U(rng), t0 = U(rng);
                const double ws = 0.5 * U(rng), wt = 0.5 * U(rng);
                const ParamBox to{Interval(s0 * (1 - ws), s0 * (1 - ws) + ws),
                                  Interval(t0 * (1 - wt), t0 * (1 - wt) + wt)};
                ParamBox got;
                if (!restrict_mark(arena, sh, m, to, out.data(), got)) {
                    CHECK((intersect(to.s, m.box.s).is_empty() ||
                           intersect(to.t, m.box.t).is_empty()));
                    continue;
                }
                ++restricted;
                const IVec3 cam = subpatch_hull(out.data(), sh);
                const IVec<3> world = shader.world_hull(out.data(), sh);
                IVec3 ds, dt;
                const bool derivatives = subpatch_derivatives(out.data(), sh, got, cam, ds, dt);
                CHECK((derivatives || got.s.width() < 1e-9 || got.t.width() < 1e-9));
                const Interval S = intersect(to.s, m.box.s), T = intersect(to.t, m.box.t);
                for (int k = 0; k < 25; ++k) {
                    const double s = S.lo() + (S.hi() - S.lo()) * (k % 5) / 4.0;
                    const double t = T.lo() + (T.hi() - T.lo()) * (k / 5) / 4.0;
                    const Vec3 P = evaluate_point(pp.patch, s, t);
                    const Vec3 W = ps.frame.to_world(P);
                    const SurfacePoint F = evaluate(pp.patch, s, t);
                    for (int c = 0; c < 3; ++c) {
                        CHECK(holds(cam[c], P[c]));
                        CHECK(holds(world[c], W[c]));
                        if (!derivatives) continue;
                        CHECK(holds(ds[c], F.du[c]));
                        CHECK(holds(dt[c], F.dv[c]));
                    }
                    ++checked;
                    rational += derivatives && sh.dim == 4;
                }
            }
        }
        CHECK(restricted > 100);
        CHECK(checked > 2500);
    }
    CHECK(rational > 100);
}
