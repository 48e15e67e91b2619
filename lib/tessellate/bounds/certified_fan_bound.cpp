// SPDX-License-Identifier: MIT
// certified_fan_bound (error_bound.h): the bound of a subpatch's final fan
// over its ring, phi shared with the neighbouring fans (PhiMemo).
#include <seamless/base/check.h>
#include <seamless/base/min_max3.h>
#include <seamless/tessellate/bounds/error_bound.h>
#include <seamless/tessellate/bounds/fan_phi.h>
#include <seamless/tessellate/bounds/net_bounds.h>
#include <seamless/tessellate/bounds/surface_feet.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <span>
#include <utility>
#include <vector>

namespace seamless {
using namespace feet;
namespace {

// split_bounds over the net of a box; out of line, so that its 14 KB net is
// not in the frame of the refined triangles' loop, which rarely needs it.
[[gnu::noinline]] SplitBounds box_split_bounds(const BezierPatch& patch, double s0, double s1,
                                               double t0, double t1, Vec3 centre, Vec3 n) {
    return split_bounds(box_net(patch, s0, s1, t0, t1, centre), n);
}

// Step (3): the bound on every refined triangle, from the derivative bounds
// of `net` over `box`, without the rounding allowance.
double refined_bound(const Fan& fan, const RefinedPhi& phi, int m, const Net& net,
                     const ParamBox& box, double enough) {
    const BezierPatch& patch = fan.patch;
    const std::span<const RingPoint> ring = fan.ring;
    const Vec3 centre = fan.centre;
    const size_t n = ring.size();
    const double bs0 = box.s0, bs1 = box.s1, bt0 = box.t0, bt1 = box.t1;
    constexpr int K = RefinedPhi::K;
    auto node = [&phi](size_t k, int a, int c) -> const Node& { return phi.node(k, a, c); };
    const Vec3 diag = cross(ring[0].position - centre, ring[n / 2].position - centre);
    // The largest square: the root is monotone and correctly rounded, so the
    // root of the largest square is the largest root, bit for bit, and no root
    // sits on the chain from one refined triangle to the next.
    double bound2 = 0;
    for (size_t k = 0; k < n; ++k) {
        const size_t k1 = (k + 1) % n;
        Vec3 nk = cross(ring[k].position - centre, ring[k1].position - centre);
        const double len = norm(nk);
        nk = len > 1e-300 && std::isfinite(len) ? nk / len : normalize(diag);
        const SplitBounds nb = split_bounds(net, nk);
        // |n.g| and the tangential |g - (n.g) n| once per refined vertex (each
        // is a vertex of up to six refined triangles).
        double gn[K][K], gt[K][K];
        for (int a = 0; a <= m; ++a)
            for (int c = 0; a + c <= m; ++c) {
                const Vec3& g = node(k, a, c).g;
                const double dn = dot(g, nk);
                gn[a][c] = std::abs(dn);
                gt[a][c] = norm(g - dn * nk);
            }
        auto tri = [&](int a0, int c0, int a1, int c1, int a2, int c2)
            __attribute__((always_inline)) {
            const Param &u0 = node(k, a0, c0).u, &u1 = node(k, a1, c1).u, &u2 = node(k, a2, c2).u;
            const double gnt = max3(gn[a0][c0], gn[a1][c1], gn[a2][c2]);
            const double gtt = max3(gt[a0][c0], gt[a1][c1], gt[a2][c2]);
            const double s0 = min3(u0.s, u1.s, u2.s), s1 = max3(u0.s, u1.s, u2.s);
            const double t0 = min3(u0.t, u1.t, u2.t), t1 = max3(u0.t, u1.t, u2.t);
            const double ds = (s1 - s0) / (bs1 - bs0), dt = (t1 - t0) / (bt1 - bt0);
            double Rn = taylor_remainder(nb.normal, ds, dt);
            double R = taylor_remainder(nb.tangential, ds, dt);
            // Only where it can raise the running maximum above `enough`
            // (lossless when enough = 0); the root taken only here.
            if (R > gnt + Rn && s1 > s0 && t1 > t0 &&
                (gnt + Rn) * (gnt + Rn) + (gtt + R) * (gtt + R) > [&] {
                    const double top = std::max(std::sqrt(bound2), enough);
                    return top * top;
                }()) {
                // The tangential remainder dominates (a pole's sector, a
                // strongly varying speed): bounds over phi(sigma)'s box alone.
                const SplitBounds ln = box_split_bounds(patch, s0, s1, t0, t1, centre, nk);
                Rn = std::min(Rn, taylor_remainder(ln.normal, 1, 1));
                R = std::min(R, taylor_remainder(ln.tangential, 1, 1));
            }
            const double en = gnt + Rn, et = gtt + R;
            bound2 = std::max(bound2, en * en + et * et);
        };
        for (int a = 0; a < m; ++a)
            for (int c = 0; a + c < m; ++c) {
                tri(a, c, a + 1, c, a, c + 1);
                if (a + c + 2 <= m) tri(a + 1, c, a + 1, c + 1, a, c + 1);
            }
    }
    return std::sqrt(bound2) * (1 + 64 * kEps);
}

// The bound of certified_fan_bound with every fan triangle refined m times
// (m a multiple of kSideRefinement), without the rounding allowance. phi at
// the refined vertices on the radial edges and inside the fan triangles takes
// up to `steps` Gauss-Newton steps toward the foot; 0: phi is the parameter
// map there, the parametric distance (looser where the parametrisation
// drifts). The shared sides' points always take the same steps, so the fans
// sharing them agree whatever `steps` each one takes. A refined triangle's
// bound at or below `enough` (0: none) is not tightened further (a tolerance
// needs no bound below itself).
double certified_fan_bound_at(const Fan& fan, int m, int steps, double enough, PhiMemo& memo) {
    // (1) phi at the refined vertices of every fan triangle.
    RefinedPhi phi(fan, m, steps, memo);
    phi.radial_edges();
    for (size_t k = 0; k < fan.ring.size(); ++k) phi.triangle(k);
    // (2) Derivative bounds over the box of all those parameters.
    const ParamBox box = phi.box();
    const Net net = box_net(fan.patch, box.s0, box.s1, box.t0, box.t1, fan.centre);
    // (3) The bound on every refined triangle.
    return refined_bound(fan, phi, m, net, box, enough);
}

} // namespace

double certified_fan_bound(const BezierPatch& patch, const ParamRect& r, int depth, Vec3 centre,
                           std::span<const RingPoint> ring, double scale, double target,
                           bool refine) {
    const size_t n = ring.size();
    SEAMLESS_CHECK(n >= 3, "a fan ring of fewer than three points");
    // On the heap (400 KB), one thread_local access (a call in a shared library).
    thread_local std::unique_ptr<PhiMemo> memo_store;
    if (!memo_store) memo_store = std::make_unique<PhiMemo>();
    PhiMemo& memo = *memo_store;
    memo.use(patch);
    const Surface S(patch, memo.power ? &memo.pb : nullptr);
    const Fan fan{patch, S, r, centre, ring};
    // The evaluator's own rounding (power basis) on top of the usual allowance.
    const double allowance =
        rounding_allowance(depth + 4 * BezierPatch::kMaxOrder, scale) + S.error();
    // A tolerance needs a bound at or below it, not the tightest one: the
    // coarsest refinement first (phi on the shared sides is the same for every
    // m, so the fans stay continuous whatever m each one takes). Both results
    // are sups over a valid phi, so the smaller one is a bound too.
    double coarse = std::numeric_limits<double>::infinity();
    // What each refined triangle's bound may reach with the result <= target.
    const double enough = target > 0 ? std::max(target - allowance, 0.0) * (1 - 128 * kEps) : 0;
    if (target > 0) {
        // Without feet inside the fan first: most fans certify so, with one
        // evaluation per refined vertex.
        for (int steps : {0, kFootSteps}) {
            coarse =
                std::min(coarse, certified_fan_bound_at(fan, kSideRefinement, steps, enough, memo) +
                                     allowance);
            if (coarse <= target) return coarse;
        }
        if (!refine) return coarse;
    }
    // m: the tangential remainder of an unrefined fan triangle of the subpatch
    // against its normal remainder (about the geometric deviation).
    int m = kSideRefinement;
    {
        const Net net =
            box_net(patch, param_of(r.s0), param_of(r.s1), param_of(r.t0), param_of(r.t1), centre);
        const DerivativeBounds full = derivative_bounds(net);
        const Vec3 nz = normalize(cross(ring[0].position - centre, ring[n / 2].position - centre));
        const double R1 = taylor_remainder(full, 1, 1);
        const double Rn1 = taylor_remainder(split_bounds(net, nz).normal, 1, 1);
        while (m < kMaxCertifyRefinement && R1 > 0.3 * m * m * Rn1) m *= 2;
    }
    if (m == kSideRefinement && target > 0) return coarse;
    return std::min(coarse, certified_fan_bound_at(fan, m, kFootSteps, enough, memo) + allowance);
}

} // namespace seamless
