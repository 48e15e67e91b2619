// SPDX-License-Identifier: MIT
#include <tessellate/trimmed/bounds/bound_cases.h>

#include <seamless/tessellate/trimmed/bounds/pole_fan.h>
#include <seamless/tessellate/trimmed/faces/triangle_distance.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace seamless;

namespace {

// A cone with its apex at the origin, radius v at height v, v in [0, 1]: the
// side v = 0 collapses to the apex.
BSplineSurface cone_apex_at_origin() {
    return test::revolved_segment(0, 0, 1, 1);
}

} // namespace

TEST_CASE("a pole fan is paired geometrically also with its apex corners a rounding off the side") {
    const BSplineSurface s = cone_apex_at_origin();
    const TriangleBound bound(s, true, false);
    const double h = 0.2;
    const int n = 8;
    for (double off : {0.0, -3e-14, 2e-14}) {
        INFO("apex corners at v = " << off);
        std::vector<RunTriangle> run(n);
        for (int k = 0; k < n; ++k) {
            const double ul = double(k) / n, ur = double(k + 1) / n;
            RunTriangle& t = run[k];
            t.uv = {UV{(ul + ur) / 2, off}, UV{ul, h}, UV{ur, h}};
            t.Q = {Vec3{0, 0, 0}, evaluate(s, ul, h).point, evaluate(s, ur, h).point};
            t.id = {0, 1 + k, 1 + (k + 1) % n};
        }
        const std::vector<UV> side{UV{0, 0}, UV{1, 0}};
        std::vector<char> handled;
        const double b = pole_fan_bounds(bound, s, run, side, handled);
        CHECK(std::count(handled.begin(), handled.end(), 1) == n);
        REQUIRE(std::isfinite(b));
        // Both ways: the cone under the ring is within b of the fan, and the
        // fan's triangles within b of the cone (distance to the cone
        // x^2 + y^2 = z^2: |r - z| / sqrt 2).
        double farthest = 0, sag = 0;
        for (int i = 0; i <= 80; ++i)
            for (int j = 0; j <= 20; ++j) {
                const Vec3 p = evaluate(s, i / 80.0, h * j / 20.0).point;
                double nearest = 1e300;
                for (const RunTriangle& t : run)
                    nearest = std::min(nearest, point_triangle_distance(p, t.Q[0], t.Q[1], t.Q[2]));
                farthest = std::max(farthest, nearest);
            }
        for (const RunTriangle& t : run)
            for (int a = 0; a <= 10; ++a)
                for (int c = 0; a + c <= 10; ++c) {
                    const Vec3 x =
                        (1 - (a + c) / 10.0) * t.Q[0] + a / 10.0 * t.Q[1] + c / 10.0 * t.Q[2];
                    sag = std::max(sag, std::abs(std::hypot(x.x, x.y) - x.z) / std::sqrt(2.0));
                }
        INFO("bound " << b << ", surface to fan " << farthest << ", fan to surface " << sag);
        CHECK(farthest <= b);
        CHECK(sag <= b);
        CHECK(b <= 3 * std::max(farthest, sag)); // geometric: no drift along the ring
    }
}
