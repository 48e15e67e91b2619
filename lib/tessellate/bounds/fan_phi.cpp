// SPDX-License-Identifier: MIT
#include <seamless/tessellate/bounds/fan_phi.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace seamless::feet {
namespace {

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

} // namespace

void PhiMemo::use(const BezierPatch& b) {
    bool same = generation != 0 && b.p == patch.p && b.q == patch.q && b.rational == patch.rational;
    for (int i = 0; i <= b.p && same; ++i)
        same = std::memcmp(&b.at(i, 0), &patch.at(i, 0), (b.q + 1) * sizeof(HPoint)) == 0;
    if (same) return;
    patch = b;
    ++generation;
    power = has_power_basis(b);
    if (power) pb = power_basis(b);
}

namespace {

Node vertex_phi(const Surface& b, const RingPoint& p, PhiMemo& memo) {
    PhiMemo::Vertex& e = memo.vertices[PhiMemo::slot(PhiMemo::hash(p, 1))];
    if (e.generation == memo.generation && PhiMemo::same(e.p, p)) return e.phi;
    e = {memo.generation, p, vertex_phi(b, p)};
    return e.phi;
}

} // namespace

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

} // namespace seamless::feet
