// SPDX-License-Identifier: MIT
// certified_fan_bound (error_bound.h): the bound of a subpatch's final fan
// over its ring, phi shared with the neighbouring fans (PhiMemo).
#include <seamless/base/check.h>
#include <seamless/base/min_max3.h>
#include <seamless/tessellate/bounds/error_bound.h>
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

// Sides shared by two fans are split into kSideRefinement pieces, the same
// for both; phi is linear between those points. Inside, a fan triangle is
// refined m = kSideRefinement * 2^k times (k chosen from its derivative bounds).
// Between the shared points phi is linear in the parameters, not a foot, so
// the tangential drift there counts in full: with 2 pieces a fan whose four
// triangles passed at 0.9 of a tolerance could certify at 1.25 of it (teapot,
// lid seams) and the passes never ended; with 4 they agree within a few percent.
constexpr int kSideRefinement = 4;
constexpr int kMaxCertifyRefinement = 16;
// Gauss-Newton steps of phi toward the foot at the refined vertices.
constexpr int kFootSteps = 2;

// phi at a mesh vertex, a function of its grid point and position alone, so
// every fan sharing the vertex agrees and phi is continuous over the patch.
// Vertices on the patch's sides stay; inner vertices move toward their foot,
// at most the spacing of the coarsest dyadic grid line through them.
Param param(const RingPoint& p) {
    return {p.fs >= 0 ? p.fs : param_of(p.s), p.ft >= 0 ? p.ft : param_of(p.t)};
}

Node vertex_phi(const Surface& b, const RingPoint& p) {
    const int gs = p.s, gt = p.t;
    const Vec3 x = p.position;
    const Param w = param(p);
    // A seam vertex of another patch lies on this patch's side: phi keeps it,
    // as it keeps the vertices on the patch's sides.
    const bool s_side = gs == 0 || gs == kParamOne, t_side = gt == 0 || gt == kParamOne;
    if (gs < 0 || gt < 0 || s_side || t_side) return {w, b.point(w.s, w.t) - x};
    auto spacing = [](int i) { return param_of(i & -i); }; // lowest set bit
    const double limit = std::max(spacing(gs), spacing(gt));
    Vec3 g;
    const Param u = foot_iterated(b, x, w, limit, 3, g);
    return {u, g};
}

bool on_patch_side(const RingPoint& a, const RingPoint& b) {
    return (a.s == b.s && (a.s == 0 || a.s == kParamOne)) ||
           (a.t == b.t && (a.t == 0 || a.t == kParamOne));
}

// phi at a ring vertex and at a shared side's points is a function of the
// patch and those ring points alone (that is what keeps phi continuous), and
// each is met by every fan sharing it (a side by two, a vertex by up to four)
// and by every refinement tried. PhiMemo keeps them per thread for the patch
// asked about last: a hit is a value computed from the bitwise same inputs,
// so the results do not depend on the order of the fans or the thread count.
// Direct-mapped; a hit compares the whole key bit for bit.
struct PhiMemo {
    static constexpr int kSlots = 1024;
    struct Vertex {
        std::uint64_t generation = 0;
        RingPoint p;
        Node phi;
    };
    struct Side {
        std::uint64_t generation = 0;
        RingPoint lo, hi;
        Node canon[kSideRefinement + 1];
    };
    std::uint64_t generation = 0; // 0: nothing kept
    BezierPatch patch;
    // power_basis(patch) when it has one (the bounds run over a patch's
    // subpatches in order, so it is made once per patch and thread).
    bool power = false;
    PowerBasisPatch pb;
    std::array<Vertex, kSlots> vertices;
    std::array<Side, kSlots> sides;

    // Starts a new generation when `b` is not the patch of the last call:
    // its control points compared (only those within its degrees are read).
    void use(const BezierPatch& b) {
        bool same =
            generation != 0 && b.p == patch.p && b.q == patch.q && b.rational == patch.rational;
        for (int i = 0; i <= b.p && same; ++i)
            same = std::memcmp(&b.at(i, 0), &patch.at(i, 0), (b.q + 1) * sizeof(HPoint)) == 0;
        if (same) return;
        patch = b;
        ++generation;
        power = has_power_basis(b);
        if (power) pb = power_basis(b);
    }
    static bool same(const RingPoint& a, const RingPoint& b) {
        return std::memcmp(&a, &b, sizeof(RingPoint)) == 0;
    }
    static std::uint64_t hash(const RingPoint& a, std::uint64_t h) {
        std::uint64_t w[sizeof(RingPoint) / 8];
        std::memcpy(w, &a, sizeof w);
        for (std::uint64_t x : w) h = (h ^ x) * 0x9E3779B97F4A7C15ull;
        return h;
    }
    static int slot(std::uint64_t h) { return static_cast<int>((h ^ (h >> 29)) >> 54); }
};
// Keys compared and hashed bit for bit: no padding in a RingPoint.
static_assert(sizeof(RingPoint) == 2 * sizeof(int) + sizeof(Vec3) + 2 * sizeof(double) &&
              sizeof(RingPoint) % 8 == 0);

Node vertex_phi(const Surface& b, const RingPoint& p, PhiMemo& memo) {
    PhiMemo::Vertex& e = memo.vertices[PhiMemo::slot(PhiMemo::hash(p, 1))];
    if (e.generation == memo.generation && PhiMemo::same(e.p, p)) return e.phi;
    e = {memo.generation, p, vertex_phi(b, p)};
    return e.phi;
}

// split_bounds over the net of a box; out of line, so that its 14 KB net is
// not in the frame of the refined triangles' loop, which rarely needs it.
[[gnu::noinline]] SplitBounds box_split_bounds(const BezierPatch& patch, double s0, double s1,
                                               double t0, double t1, Vec3 centre, Vec3 n) {
    return split_bounds(box_net(patch, s0, s1, t0, t1, centre), n);
}

// A fan as its bound reads it: the subpatch `r` of `patch` (evaluated by
// `S`), its centre vertex and its ring.
struct Fan {
    const BezierPatch& patch;
    const Surface& S;
    const ParamRect& r;
    Vec3 centre;
    std::span<const RingPoint> ring;
};

constexpr int K = kMaxCertifyRefinement + 1;

// The box of a subpatch's parameters and its feet's.
struct ParamBox {
    double s0, s1, t0, t1;
};

// phi at the refined vertices of every fan triangle, refined m times: grid k,
// a, c is centre + a/m (P - centre) + c/m (Q - centre), P Q the ring's k-th
// side. On the radial edges and inside the fan triangles (no other fan's phi
// meets them) phi takes up to `steps` Gauss-Newton steps toward the foot.
class RefinedPhi {
  public:
    RefinedPhi(const Fan& fan, int m, int steps, PhiMemo& memo);
    Node& node(size_t k, int a, int c) const { return grids_[(k * K + a) * K + c]; }
    // phi on every radial edge, from the centre to each ring vertex.
    void radial_edges();
    // phi on fan triangle k's edges and inside it.
    void triangle(size_t k);
    // Step (2): the box of all refined vertices' parameters.
    ParamBox box() const;

  private:
    void shared_side(size_t k);
    void inside(size_t k);

    const Fan& fan_;
    int m_, steps_;
    PhiMemo& memo_;
    double sc_, tc_, inner_limit_;
    Node centre_node_;
    // Plain pointers: each thread_local access in a shared library is a call.
    std::array<Node, K>* radial_;
    Node* grids_;
};

RefinedPhi::RefinedPhi(const Fan& fan, int m, int steps, PhiMemo& memo)
    : fan_(fan), m_(m), steps_(steps), memo_(memo) {
    const ParamRect& r = fan.r;
    sc_ = 0.5 * (param_of(r.s0) + param_of(r.s1));
    tc_ = 0.5 * (param_of(r.t0) + param_of(r.t1));
    centre_node_ = {{sc_, tc_}, fan.S.point(sc_, tc_) - fan.centre};
    inner_limit_ = 0.5 * std::max(param_of(r.s1) - param_of(r.s0), param_of(r.t1) - param_of(r.t0));
    const size_t n = fan.ring.size();
    thread_local std::vector<std::array<Node, K>> radial_store;
    thread_local std::vector<Node> grid_store;
    radial_store.resize(n);
    grid_store.resize(n * K * K);
    radial_ = radial_store.data();
    grids_ = grid_store.data();
}

void RefinedPhi::radial_edges() {
    const Surface& S = fan_.S;
    const std::span<const RingPoint> ring = fan_.ring;
    const Vec3 centre = fan_.centre;
    const double sc = sc_, tc = tc_, inner_limit = inner_limit_;
    const int m = m_, steps = steps_;
    std::array<Node, K>* const radial = radial_;
    for (size_t i = 0; i < ring.size(); ++i) {
        radial[i][0] = centre_node_;
        radial[i][m] = vertex_phi(S, ring[i], memo_);
        const Param p = param(ring[i]);
        for (int a = 1; a < m; ++a) {
            const double f = static_cast<double>(a) / m;
            const Param w{sc + f * (p.s - sc), tc + f * (p.t - tc)};
            const Vec3 x = centre + f * (ring[i].position - centre);
            Vec3 g;
            const Param u = foot_iterated(S, x, w, inner_limit, steps, g);
            radial[i][a] = {u, g};
        }
    }
}

void RefinedPhi::triangle(size_t k) {
    const size_t k1 = (k + 1) % fan_.ring.size();
    for (int a = 0; a <= m_; ++a) node(k, a, 0) = radial_[k][a];
    for (int c = 0; c <= m_; ++c) node(k, 0, c) = radial_[k1][c];
    shared_side(k);
    inside(k);
}

// The side P Q: points in a canonical order (from the endpoint with the
// smaller grid point), the same for the fan on its other side, which meets
// the same kSideRefinement + 1 points in PhiMemo.
void RefinedPhi::shared_side(size_t k) {
    const Surface& S = fan_.S;
    const int m = m_, side_step = m / kSideRefinement;
    const RingPoint &P = fan_.ring[k], &Q = fan_.ring[(k + 1) % fan_.ring.size()];
    const bool forward = std::pair(param(P).s, param(P).t) < std::pair(param(Q).s, param(Q).t);
    const RingPoint& lo = forward ? P : Q;
    const RingPoint& hi = forward ? Q : P;
    const Node& nlo = forward ? node(k, m, 0) : node(k, 0, m);
    const Node& nhi = forward ? node(k, 0, m) : node(k, m, 0);
    const Param plo = param(lo), phi_ = param(hi);
    const bool side = on_patch_side(lo, hi);
    const double seg_limit = std::max(std::abs(phi_.s - plo.s), std::abs(phi_.t - plo.t));
    PhiMemo::Side& memo_side = memo_.sides[PhiMemo::slot(PhiMemo::hash(hi, PhiMemo::hash(lo, 2)))];
    Node* const canon = memo_side.canon;
    const bool known = memo_side.generation == memo_.generation &&
                       PhiMemo::same(memo_side.lo, lo) && PhiMemo::same(memo_side.hi, hi);
    if (!known) {
        memo_side.generation = memo_.generation;
        memo_side.lo = lo;
        memo_side.hi = hi;
        canon[0] = nlo;
        canon[kSideRefinement] = nhi;
    }
    for (int j = 1; j < kSideRefinement && !known; ++j) {
        const double f = static_cast<double>(j) / kSideRefinement;
        const Param w{plo.s + f * (phi_.s - plo.s), plo.t + f * (phi_.t - plo.t)};
        const Vec3 x = lo.position + f * (hi.position - lo.position);
        Node& cn = canon[j];
        if (side) {
            // Along the patch's side, between phi(lo) and phi(hi).
            const double z =
                foot_on_line(S, x, {nlo.u, nhi.u, 0.0, 1.0}, f, 0.5 / kSideRefinement, cn.g);
            cn.u = {nlo.u.s + z * (nhi.u.s - nlo.u.s), nlo.u.t + z * (nhi.u.t - nlo.u.t)};
        } else {
            cn.u = foot_iterated(S, x, w, seg_limit, kFootSteps, cn.g);
        }
    }
    // The refined points between: phi linear between the shared points.
    for (int j = 1; j < m; ++j) {
        const int c = forward ? j : m - j;
        if (j % side_step == 0) {
            node(k, m - c, c) = canon[j / side_step];
            continue;
        }
        const Node& a0 = canon[j / side_step];
        const Node& a1 = canon[j / side_step + 1];
        const double f = static_cast<double>(j % side_step) / side_step;
        const double fx = static_cast<double>(j) / m;
        Node& x = node(k, m - c, c);
        x.u = {a0.u.s + f * (a1.u.s - a0.u.s), a0.u.t + f * (a1.u.t - a0.u.t)};
        x.g = S.point(x.u.s, x.u.t) - (lo.position + fx * (hi.position - lo.position));
    }
}

// Inside fan triangle k.
void RefinedPhi::inside(size_t k) {
    const Surface& S = fan_.S;
    const Vec3 centre = fan_.centre;
    const double sc = sc_, tc = tc_, inner_limit = inner_limit_;
    const int m = m_, steps = steps_;
    const RingPoint &P = fan_.ring[k], &Q = fan_.ring[(k + 1) % fan_.ring.size()];
    const Param pp = param(P), pq = param(Q);
    for (int a = 1; a < m; ++a)
        for (int c = 1; a + c < m; ++c) {
            const double fa = static_cast<double>(a) / m, fc = static_cast<double>(c) / m;
            const Param w{sc + fa * (pp.s - sc) + fc * (pq.s - sc),
                          tc + fa * (pp.t - tc) + fc * (pq.t - tc)};
            const Vec3 x = centre + fa * (P.position - centre) + fc * (Q.position - centre);
            Node& y = node(k, a, c);
            y.u = foot_iterated(S, x, w, inner_limit, steps, y.g);
        }
}

// phi is linear on each refined triangle, so phi(sigma) lies in the box of
// its three vertices, inside this one (the subpatch plus the feet's moves).
ParamBox RefinedPhi::box() const {
    const ParamRect& r = fan_.r;
    double bs0 = param_of(r.s0), bs1 = param_of(r.s1), bt0 = param_of(r.t0), bt1 = param_of(r.t1);
    const int m = m_;
    for (size_t k = 0; k < fan_.ring.size(); ++k)
        for (int a = 0; a <= m; ++a)
            for (int c = 0; a + c <= m; ++c) {
                const Param& u = node(k, a, c).u;
                bs0 = std::min(bs0, u.s), bs1 = std::max(bs1, u.s);
                bt0 = std::min(bt0, u.t), bt1 = std::max(bt1, u.t);
            }
    return {bs0, bs1, bt0, bt1};
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
                           std::span<const RingPoint> ring, double scale, double target) {
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
