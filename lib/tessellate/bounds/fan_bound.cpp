// SPDX-License-Identifier: MIT
// fan_bound (error_bound.h): the four-triangle bound the subdivision
// accepts a subpatch by, on the subpatch's own net.
#include <seamless/base/min_max3.h>
#include <seamless/tessellate/bounds/error_bound.h>
#include <seamless/tessellate/bounds/net_bounds.h>
#include <seamless/tessellate/bounds/surface_feet.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace seamless {
using namespace feet;
namespace {

struct FanResult {
    double bound = 0, largest_g = 0;
};

// The four-triangle fan of a subpatch as its bound reads it: the surface, the
// centre vertex and the corners V, each triangle's unit normal n and the
// net's bounds split along it; `fixed`: S at the centre (1/2, 1/2) and at the
// corners, which phi keeps.
struct FourFan {
    const Surface& b;
    Vec3 centre;
    const std::array<Vec3, 4>& V;
    const std::array<Vec3, 4>& n;
    const std::array<SplitBounds, 4>& nb;
    const std::array<Vec3, 5>& fixed;
};

constexpr int K = kMaxFanRefinement + 1;

// phi on the radial edges (centre to corner k), shared by two fan triangles.
void radial_edges(const FourFan& fan, int m, Node (&radial)[4][K]) {
    const Surface& b = fan.b;
    const Vec3 centre = fan.centre;
    const std::array<Vec3, 4>& V = fan.V;
    for (int k = 0; k < 4; ++k)
        for (int a = 0; a <= m; ++a) {
            const double f = static_cast<double>(a) / m;
            const Param w{kCentre.s + f * (kCorner[k].s - kCentre.s),
                          kCentre.t + f * (kCorner[k].t - kCentre.t)};
            const Vec3 x = centre + f * (V[k] - centre);
            Param u = w;
            Vec3 g;
            if (a == 0 || a == m) {
                u = a == 0 ? kCentre : kCorner[k];
                g = fan.fixed[a == 0 ? 0 : k + 1] - x;
            } else {
                u = foot(b, x, w, 0.5 / m, g);
            }
            radial[k][a] = {u, g};
        }
}

// phi at fan triangle k's refined vertices: grid[a][b] is centre + a/m (V[k]
// - centre) + b/m (V[k+1] - centre).
void triangle_grid(const FourFan& fan, int m, int k, const Node (&radial)[4][K],
                   Node (&grid)[K][K]) {
    const Surface& b = fan.b;
    const Vec3 centre = fan.centre;
    const std::array<Vec3, 4>& V = fan.V;
    const int k1 = (k + 1) % 4;
    for (int a = 0; a <= m; ++a) grid[a][0] = radial[k][a];
    for (int c = 0; c <= m; ++c) grid[0][c] = radial[k1][c];
    // Side k: a + c = m, tau = c / m from corner k; monotone in tau.
    double lo = 0;
    for (int c = 1; c < m; ++c) {
        const int a = m - c;
        const double tau = static_cast<double>(c) / m;
        const Vec3 x = V[k] + tau * (V[k1] - V[k]);
        Vec3 g;
        lo = foot_on_line(b, x, {kCorner[k], kCorner[k1], lo, 1.0}, tau, 0.5 / m, g);
        const Param u{kCorner[k].s + lo * (kCorner[k1].s - kCorner[k].s),
                      kCorner[k].t + lo * (kCorner[k1].t - kCorner[k].t)};
        grid[a][c] = {u, g};
    }
    // Interior.
    for (int a = 1; a < m; ++a)
        for (int c = 1; a + c < m; ++c) {
            const double fa = static_cast<double>(a) / m, fc = static_cast<double>(c) / m;
            const Param w{
                kCentre.s + fa * (kCorner[k].s - kCentre.s) + fc * (kCorner[k1].s - kCentre.s),
                kCentre.t + fa * (kCorner[k].t - kCentre.t) + fc * (kCorner[k1].t - kCentre.t)};
            const Vec3 x = centre + fa * (V[k] - centre) + fc * (V[k1] - centre);
            Vec3 g;
            const Param u = foot(b, x, w, 0.5 / m, g);
            grid[a][c] = {u, g};
        }
}

// The bound on fan triangle k's refined triangles, raising the largest square
// `bound2` and the largest |g| met.
void triangle_bound(const FourFan& fan, int m, int k, const Node (&grid)[K][K], double& bound2,
                    double& largest_g) {
    const Vec3 nk = fan.n[k];
    const SplitBounds& nb = fan.nb[k];
    // |g|, |n.g| and the tangential |g - (n.g) n| once per refined vertex
    // (a vertex of up to six refined triangles; the same values and the
    // same maxima, in the same order, as per triangle).
    double gg[K][K], gn[K][K], gt[K][K];
    for (int a = 0; a <= m; ++a)
        for (int c = 0; a + c <= m; ++c) {
            const Vec3& g = grid[a][c].g;
            const double dn = dot(g, nk);
            gg[a][c] = norm(g);
            gn[a][c] = std::abs(dn);
            gt[a][c] = norm(g - dn * nk);
        }
    // Refined triangles: up (a,c),(a+1,c),(a,c+1); down (a+1,c),(a+1,c+1),(a,c+1).
    auto tri = [&](int a0, int c0, int a1, int c1, int a2, int c2) {
        double en = 0, et = 0;
        for (const auto& [a, c] : {std::pair(a0, c0), std::pair(a1, c1), std::pair(a2, c2)}) {
            largest_g = std::max(largest_g, gg[a][c]);
            en = std::max(en, gn[a][c]);
            et = std::max(et, gt[a][c]);
        }
        const Param &u0 = grid[a0][c0].u, &u1 = grid[a1][c1].u, &u2 = grid[a2][c2].u;
        const double ds = max3(u0.s, u1.s, u2.s) - min3(u0.s, u1.s, u2.s);
        const double dt = max3(u0.t, u1.t, u2.t) - min3(u0.t, u1.t, u2.t);
        en += taylor_remainder(nb.normal, ds, dt);
        et += taylor_remainder(nb.tangential, ds, dt);
        bound2 = std::max(bound2, en * en + et * et);
    };
    for (int a = 0; a < m; ++a)
        for (int c = 0; a + c < m; ++c) {
            tri(a, c, a + 1, c, a, c + 1);
            if (a + c + 2 <= m) tri(a + 1, c, a + 1, c + 1, a, c + 1);
        }
}

// The four-triangle bound with each fan triangle refined m times.
FanResult fan_bound_at(const FourFan& fan, int m) {
    // Left unset until written (Node's members would be zeroed on every call).
    union RadialStore {
        RadialStore() {}
        Node at[4][K];
    } radial_store;
    auto& radial = radial_store.at;
    radial_edges(fan, m, radial);
    // The largest square (its root, taken once, is the largest root bit for
    // bit: the root is monotone and correctly rounded).
    double bound2 = 0, largest_g = 0;
    union GridStore {
        GridStore() {}
        Node at[K][K];
    } grid_store;
    auto& grid = grid_store.at;
    for (int k = 0; k < 4; ++k) {
        triangle_grid(fan, m, k, radial, grid);
        triangle_bound(fan, m, k, grid, bound2, largest_g);
    }
    // Relative rounding of the sums above.
    return {std::sqrt(bound2) * (1 + 64 * kEps), largest_g};
}

double fan_bound_of(const Surface& S, Vec3 centre, const std::array<Vec3, 4>& V, double target) {
    const BezierPatch& b = S.patch;
    const Net net = net_of(b, centre);
    const DerivativeBounds full = derivative_bounds(net);

    // Unit normals of the fan triangles (any unit vector keeps the bound valid:
    // degenerate triangles borrow the subpatch's corner normal).
    std::array<Vec3, 4> n{};
    const Vec3 diag = cross(V[2] - V[0], V[3] - V[1]);
    for (int k = 0; k < 4; ++k) {
        const Vec3 c = cross(V[k] - centre, V[(k + 1) % 4] - centre);
        const double len = norm(c);
        n[k] = len > 1e-300 && std::isfinite(len) ? c / len : normalize(diag);
    }
    std::array<SplitBounds, 4> nb{};
    for (int k = 0; k < 4; ++k) nb[k] = split_bounds(net, n[k]);

    // m: the tangential remainder of an unrefined fan triangle (extents 1 x 1/2)
    // against its normal remainder (about the geometric deviation) or the target.
    double R1 = 0, Rn1 = 0;
    for (int k = 0; k < 4; ++k) {
        const double ds = k % 2 == 0 ? 1.0 : 0.5, dt = k % 2 == 0 ? 0.5 : 1.0;
        R1 = std::max(R1, taylor_remainder(full, ds, dt));
        Rn1 = std::max(Rn1, taylor_remainder(nb[k].normal, ds, dt));
    }
    const double want = std::max(0.4 * Rn1, 0.2 * target);
    int m = 1;
    if (R1 > 0)
        m = want > 0 ? static_cast<int>(std::ceil(std::sqrt(R1 / want))) : kMaxFanRefinement;
    m = std::clamp(m, 1, kMaxFanRefinement);
    // Evaluated once for both refinements tried (each radial edge starts at
    // the centre).
    const std::array<Vec3, 5> fixed{
        S.point(kCentre.s, kCentre.t), S.point(kCorner[0].s, kCorner[0].t),
        S.point(kCorner[1].s, kCorner[1].t), S.point(kCorner[2].s, kCorner[2].t),
        S.point(kCorner[3].s, kCorner[3].t)};
    const FourFan fan{S, centre, V, n, nb, fixed};
    if (target > 0 && m > 2) {
        // Cheap first: m = 2 may already certify the target, or its refined
        // vertices, about as far from the surface as it lies, already exceed it.
        const FanResult r = fan_bound_at(fan, 2);
        if (r.bound <= target || r.largest_g > target) return r.bound;
    }
    return fan_bound_at(fan, m).bound;
}

} // namespace

double fan_bound(const BezierPatch& b, Vec3 centre, const std::array<Vec3, 4>& V, double target) {
    const Surface S(b);
    return fan_bound_of(S, centre, V, target);
}

double fan_bound(const BezierPatch& b, const PowerBasisPatch& pb, Vec3 centre,
                 const std::array<Vec3, 4>& V, double target) {
    const Surface S(b, &pb);
    return fan_bound_of(S, centre, V, target);
}

} // namespace seamless
