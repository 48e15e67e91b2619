// SPDX-License-Identifier: MIT
#include <seamless/tessellate/trimmed/bounds/pole_fan.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace seamless {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kU = std::numeric_limits<double>::epsilon() / 2;

// A side of the domain: the line uv[across] == at, the domain on the side
// `inward` (+1: above it, -1: below).
struct Side {
    int across = 0;
    double at = 0;
    int inward = 1;
    double near = 0; // a rounding of the domain's extent
    int along() const { return 1 - across; }
};

// A fan triangle: its corner on the side and the two others, by along.
struct FanTriangle {
    int k = 0; // in the run
    int pole = 0, l = 0, r = 0;
};

// The run's triangles with a corner on the side, in order along it, when
// they form one monotone strip (header); empty otherwise.
std::vector<FanTriangle> fan(const Side& side, std::span<const RunTriangle> run,
                             std::span<const UV> side_points, double& offset) {
    const int al = side.along(), ac = side.across;
    std::vector<FanTriangle> out;
    double off_side = 0; // the pole corners' distance to the side
    for (int k = 0; k < static_cast<int>(run.size()); ++k) {
        const auto& uv = run[k].uv;
        int on = 0, pole = 0;
        for (int c = 0; c < 3; ++c)
            if (std::abs(uv[c][ac] - side.at) <= side.near) ++on, pole = c;
        if (on == 0) continue;
        if (on > 1) return {};
        FanTriangle f{k, pole, (pole + 1) % 3, (pole + 2) % 3};
        if (uv[f.l][al] > uv[f.r][al]) std::swap(f.l, f.r);
        if (!(uv[f.l][al] < uv[f.r][al]) || !((uv[f.l][ac] - side.at) * side.inward > 0) ||
            !((uv[f.r][ac] - side.at) * side.inward > 0))
            return {};
        if (!out.empty() && run[out[0].k].id[out[0].pole] != run[k].id[pole]) return {};
        off_side = std::max(off_side, std::abs(uv[pole][ac] - side.at));
        out.push_back(f);
    }
    if (out.empty()) return {};
    std::sort(out.begin(), out.end(), [&](const FanTriangle& a, const FanTriangle& b) {
        return run[a.k].uv[a.l][al] < run[b.k].uv[b.l][al];
    });
    for (size_t i = 0; i + 1 < out.size(); ++i)
        if (run[out[i].k].uv[out[i].r] != run[out[i + 1].k].uv[out[i + 1].l]) return {};
    const FanTriangle &first = out.front(), &last = out.back();
    const double lo = run[first.k].uv[first.l][al], hi = run[last.k].uv[last.r][al];
    // The side's edges span exactly [lo, hi]: the fan's region (with the
    // triangles the mesh drops) ends in the vertical edges from (lo, side)
    // and (hi, side) to the first and last y.
    double from = kInf, to = -kInf;
    for (const UV& x : side_points)
        if (std::abs(x[ac] - side.at) <= side.near)
            from = std::min(from, x[al]), to = std::max(to, x[al]);
    for (const FanTriangle& f : out)
        from = std::min(from, run[f.k].uv[f.pole][al]), to = std::max(to, run[f.k].uv[f.pole][al]);
    // A file's seam or meridian a few ulps off the vertical, or its pole
    // corners a few ulps off the side: the trapezoids then miss, or add, a
    // sliver of that width (pole_fan_bounds adds the surface's change
    // across it).
    if (!(std::abs(from - lo) <= side.near && std::abs(to - hi) <= side.near)) return {};
    offset = std::max({std::abs(from - lo), std::abs(to - hi), off_side});
    return out;
}

// The bound of one fan triangle's trapezoid (header).
double trapezoid_bound(const TriangleBound& bound, const Side& side, const RunTriangle& t,
                       const FanTriangle& f) {
    const int al = side.along(), ac = side.across;
    const Vec3 P = t.Q[f.pole];
    const double dl = std::abs(t.uv[f.l][ac] - side.at), dr = std::abs(t.uv[f.r][ac] - side.at);
    // The nearer y's own coordinate: the rectangle's corner is that point.
    const double top = dl <= dr ? t.uv[f.l][ac] : t.uv[f.r][ac], h = std::min(dl, dr);
    // The mesh edges P Q_l and P Q_r at the rectangle's top.
    const Vec3 Ql = dl == h ? t.Q[f.l] : P + (h / dl) * (t.Q[f.l] - P);
    const Vec3 Qr = dr == h ? t.Q[f.r] : P + (h / dr) * (t.Q[f.r] - P);
    const double a0 = t.uv[f.l][al], a1 = t.uv[f.r][al];
    // (along, across) corners to (u, v): M's order is (u0,v0), (u1,v0), (u1,v1), (u0,v1).
    const double c0 = std::min(side.at, top), c1 = std::max(side.at, top);
    auto value = [&](double a, double c) { return c == side.at ? P : a == a0 ? Ql : Qr; };
    std::array<double, 4> box;
    std::array<Vec3, 4> M;
    if (al == 0) {
        box = {a0, a1, c0, c1};
        M = {value(a0, c0), value(a1, c0), value(a1, c1), value(a0, c1)};
    } else {
        box = {c0, c1, a0, a1};
        M = {value(a0, c0), value(a0, c1), value(a1, c1), value(a1, c0)};
    }
    double b = bound.bilinear_box(box, M);
    if (dl != dr) {
        // The triangle above: the farther y, the nearer one and the farther
        // one's foot at the rectangle's top.
        const bool left_far = dl > dr;
        UV foot = t.uv[left_far ? f.l : f.r];
        foot[ac] = top;
        b = std::max(b,
                     bound({t.uv[f.l], t.uv[f.r], foot}, {t.Q[f.l], t.Q[f.r], left_far ? Ql : Qr}));
    }
    // The mesh values at the rectangle's top are rounded points of the mesh
    // edges, where the neighbours meet: a few ulps apart.
    double qmax = 0;
    for (const Vec3& q : t.Q) qmax = std::max({qmax, std::abs(q.x), std::abs(q.y), std::abs(q.z)});
    return b + 16 * kU * qmax;
}

// True when the side's row of control points is one point (to a rounding
// of the net's extent): a pole or apex. Fans are looked for there only.
bool collapsed(const BSplineSurface& s, const Side& side) {
    const bool u_side = side.across == 0;
    const int n = u_side ? s.size_v : s.size_u;
    const int fixed = side.inward > 0 ? 0 : (u_side ? s.size_u : s.size_v) - 1;
    auto point = [&](int k) { return u_side ? s.point(fixed, k) : s.point(k, fixed); };
    const double tiny = 1e-12 * control_box(s).max_extent();
    for (int k = 1; k < n; ++k)
        if (!(distance(point(k), point(0)) <= tiny)) return false;
    return true;
}

} // namespace

double pole_fan_bounds(const TriangleBound& bound, const BSplineSurface& s,
                       std::span<const RunTriangle> run, std::span<const UV> side_points,
                       std::vector<char>& handled) {
    handled.assign(run.size(), 0);
    double worst = 0;
    const double n = 1e-9 * std::min(s.u_max() - s.u_min(), s.v_max() - s.v_min());
    const Side sides[4] = {
        {0, s.u_min(), 1, n}, {0, s.u_max(), -1, n}, {1, s.v_min(), 1, n}, {1, s.v_max(), -1, n}};
    std::vector<FanTriangle> fans[4];
    double offset[4] = {0, 0, 0, 0};
    std::vector<int> member(run.size(), 0);
    for (int i = 0; i < 4; ++i)
        if (collapsed(s, sides[i]))
            for (const FanTriangle& t : fans[i] = fan(sides[i], run, side_points, offset[i]))
                ++member[t.k];
    for (int i = 0; i < 4; ++i) {
        const Side& side = sides[i];
        const std::vector<FanTriangle>& f = fans[i];
        // A triangle of two fans (a corner of the domain) would need two
        // pairings: both fans keep the parametric bound.
        if (std::any_of(f.begin(), f.end(), [&](const FanTriangle& t) { return member[t.k] > 1; }))
            continue;
        std::vector<double> b;
        // Twice the gradient across the sliver: it is within that of the
        // trapezoids' points both ways.
        const double sliver = 2 * bound.max_gradient() * offset[i] * (1 + 1e-12);
        for (const FanTriangle& t : f)
            b.push_back(trapezoid_bound(bound, side, run[t.k], t) + sliver);
        // A fan with a trapezoid that cannot be certified keeps the
        // parametric bound whole (its pairing is one map).
        if (f.empty() || !(*std::max_element(b.begin(), b.end()) < kInf)) continue;
        for (size_t k = 0; k < f.size(); ++k) handled[f[k].k] = 1, worst = std::max(worst, b[k]);
    }
    return worst;
}

} // namespace seamless
