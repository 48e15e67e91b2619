// SPDX-License-Identifier: MIT
#include <seamless/base/check.h>
#include <seamless/spline/surface_point.h>
#include <seamless/tessellate/bounds/error_bound.h>
#include <seamless/tessellate/bounds/power_basis.h>
#include <seamless/tessellate/subdivision/planarity.h>
#include <seamless/tessellate/subdivision/subdivision.h>

#include <algorithm>
#include <cmath>
#include <deque>

namespace seamless {
namespace {

// Leaves counted locally before one subtraction from leaves_left. The refusal
// stays exact (every leaf is subtracted by the time subdivide returns, and
// splitting stops only once the total is already past the budget); the batch
// only delays when the workers see it by at most this many leaves each.
constexpr std::int64_t kLeafBatch = 64;

struct Context {
    int patch_index;
    const SubdivisionOptions& options;
    PatchTrees& trees;
    std::vector<Subpatch>& out;
    // The two halves split at each depth, reused from split to split (two
    // fresh BezierPatch per split would zero 6.4 KB). Entries beyond the
    // degrees stay as constructed.
    std::deque<std::array<BezierPatch, 2>>& halves;
    int next = 0; // the next node id without nodes (options.nodes false)
    // Leaves not yet taken from options.leaves_left: one atomic subtraction
    // per kLeafBatch leaves, not per leaf, so the workers do not contend.
    std::int64_t unflushed = 0;

    std::array<BezierPatch, 2>& half(int depth) {
        while (static_cast<int>(halves.size()) <= depth) halves.emplace_back();
        return halves[depth];
    }
};

// A subpatch whose sides along one direction are this many times as long as
// the others is elongated.
constexpr double kElongated = 16;

// The lengths of the sides along u (corners 0-1 and 3-2) and along v.
std::array<double, 2> side_lengths(const BezierPatch& b) {
    return {distance(b.corner(0), b.corner(1)) + distance(b.corner(3), b.corner(2)),
            distance(b.corner(0), b.corner(3)) + distance(b.corner(1), b.corner(2))};
}

bool elongated(const BezierPatch& b) {
    const std::array<double, 2> l = side_lengths(b);
    return std::max(l[0], l[1]) > kElongated * std::min(l[0], l[1]);
}

// True to split in u (s), false for v (t).
bool split_in_u(const BezierPatch& b) {
    const double fu = flatness_u(b), fv = flatness_v(b);
    if (fu > 2 * fv) return true;
    if (fv > 2 * fu) return false;
    const std::array<double, 2> l = side_lengths(b);
    return l[0] >= l[1];
}

// fan_accepted's fan_error when the angle criterion rejected the fan.
constexpr double kTurned = -2;

// The tolerance and angle criteria on the four-triangle fan from the centre
// over the corners; fan_error is set when the tolerance test ran to the end,
// to kTurned when the normals turned too far.
bool fan_accepted(const SubdivisionOptions& o, const BezierPatch& b, Vec3 centre,
                  const std::array<Vec3, 4>& V, double& fan_error) {
    if (o.tolerance <= 0 && o.angle <= 0) return true;
    static constexpr double kParam[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    // A polynomial bicubic subpatch in the power basis (power_basis.h) once,
    // for the quick rejection's points and the fan bound's evaluations.
    const bool power = o.tolerance > 0 && has_power_basis(b);
    // fan_bound adds no rounding allowance; not read without `power`.
    const PowerBasisPatch pb = power ? power_basis(b, false) : PowerBasisPatch{};
    auto point = [&](double s, double t) {
        return power ? evaluate_point(pb, s, t) : evaluate_point(b, s, t);
    };
    // A fan within a fraction of the tolerance is judged by the tolerance
    // alone: at a cusp or an apex inside a patch (a folded C0 surface) the
    // normals turn however small it is, as the trimmed faces' tiny
    // triangles (face_triangulation.cpp).
    double reach = 0;
    for (const Vec3& v : V) reach = std::max(reach, distance(v, centre));
    const bool angle = o.angle > 0 && !(o.tolerance > 0 && reach <= kTinyFan * o.tolerance);
    for (int k = 0; k < 4; ++k) {
        const int k1 = (k + 1) % 4;
        const Vec3 a = V[k] - centre, c = V[k1] - centre, m = cross(a, c);
        // A pole's empty triangle, also where its corners differ by rounding
        // (a sphere placed off its axes): its plane is noise.
        if (!(norm(m) > 1e-10 * norm(a) * norm(c))) continue;
        const Vec3 n = normalize(m);
        if (o.tolerance > 0) {
            // Quick rejection (not part of the proof): the surface at the
            // triangle's parameter centroid far from its plane.
            const double s = (0.5 + kParam[k][0] + kParam[k1][0]) / 3;
            const double t = (0.5 + kParam[k][1] + kParam[k1][1]) / 3;
            if (std::abs(dot(point(s, t) - centre, n)) > 1.2 * o.tolerance) return false;
            const double ms = 0.5 * (kParam[k][0] + kParam[k1][0]);
            const double mt = 0.5 * (kParam[k][1] + kParam[k1][1]);
            if (std::abs(dot(point(ms, mt) - centre, n)) > 1.2 * o.tolerance) return false;
        }
        if (angle) {
            const double cos_half = std::cos(0.5 * o.angle);
            // A pole's normal is skipped: its limit depends on the direction
            // approached from (regular_unit_normal, surface_point.h).
            Vec3 sn;
            for (const double* q : {kParam[k], kParam[k1]})
                if (regular_unit_normal(b, q[0], q[1], sn) && dot(sn, n) < cos_half) {
                    fan_error = kTurned;
                    return false;
                }
            if (regular_unit_normal(b, 0.5, 0.5, sn) && dot(sn, n) < cos_half) {
                fan_error = kTurned;
                return false;
            }
        }
    }
    if (o.tolerance > 0) {
        fan_error =
            power ? fan_bound(b, pb, centre, V, o.tolerance) : fan_bound(b, centre, V, o.tolerance);
        return fan_error <= o.tolerance;
    }
    return true;
}

// Whether subpatch `r` (net `b`, corners V) passes the criteria: planarity
// (unless `forced`), then the tolerance's and angle's verdict on its fan,
// from the memo when an earlier pass met it. fan_error as fan_accepted's.
bool criteria_accept(Context& cx, const BezierPatch& b, const ParamRect& r, Vec3 centre,
                     const std::array<Vec3, 4>& V, bool forced, double& fan_error) {
    // With a tolerance alone the planarity test is off (both eps infinite).
    const bool test_planarity = std::isfinite(cx.options.eps1) || std::isfinite(cx.options.eps2);
    bool planar =
        !forced && (!test_planarity || planarity(b).planar(cx.options.eps1, cx.options.eps2));
    if (planar) {
        FanMemo* memo = cx.options.memo;
        const std::uint64_t key = memo ? subpatch_key(cx.patch_index, r) : 0;
        const FanVerdict* known = memo ? memo->find(key) : nullptr;
        if (known) {
            planar = known->accepted;
            fan_error = known->fan_error;
        } else {
            planar = fan_accepted(cx.options, b, centre, V, fan_error);
            if (memo) (*memo)[key] = FanVerdict{planar, fan_error};
        }
    }
    return planar;
}

// Appends `leaf`, counted against the budget (SubdivisionOptions::leaves_left).
void add_leaf(Context& cx, const Subpatch& leaf) {
    std::atomic<std::int64_t>* const left = cx.options.leaves_left;
    if (left && ++cx.unflushed == kLeafBatch) {
        left->fetch_sub(kLeafBatch, std::memory_order_relaxed);
        cx.unflushed = 0;
    }
    if (cx.options.nodes) cx.trees.nodes[leaf.node].subpatch = static_cast<int>(cx.out.size());
    cx.out.push_back(leaf);
}

// The direction subpatch `r` is halved in, true for u (s). A subpatch the
// tolerance rejected: where the remainder is larger; else where it is less
// flat, unless the angle rejected an elongated subpatch flat within a
// fraction of the tolerance both ways: then across its long sides (a
// twisted patch's straight rulings, along which the normal turns though
// flatness sees nothing: halving across them never ends). A side can only
// be halved while it spans more than one grid step.
bool halve_in_u(const Context& cx, const BezierPatch& b, const ParamRect& r, double fan_error,
                bool forced) {
    const bool can_u = r.s1 - r.s0 > 1, can_v = r.t1 - r.t0 > 1;
    bool in_u;
    if (cx.options.tolerance > 0 && (fan_error >= 0 || forced)) {
        const std::array<double, 2> d = second_derivative_bounds(b);
        in_u = d[0] >= d[1];
    } else if (fan_error == kTurned && cx.options.tolerance > 0 && elongated(b) &&
               std::max(flatness_u(b), flatness_v(b)) <= kTinyFan * cx.options.tolerance) {
        in_u = side_lengths(b)[0] >= side_lengths(b)[1];
    } else {
        in_u = split_in_u(b);
    }
    if (in_u && !can_u) in_u = false;
    if (!in_u && !can_v) in_u = true;
    return in_u;
}

int recurse(Context& cx, const BezierPatch& b, ParamRect r, int depth) {
    const bool nodes = cx.options.nodes;
    const int id = nodes ? static_cast<int>(cx.trees.nodes.size()) : cx.next++;
    if (nodes) {
        cx.trees.nodes.emplace_back();
        cx.trees.nodes[id].control_hull = control_box(b);
    }
    cx.trees.depth = std::max(cx.trees.depth, depth);

    const std::array<Vec3, 4> V{b.corner(0), b.corner(1), b.corner(2), b.corner(3)};
    const Vec3 centre = exact_point(b, 0.5, 0.5);
    double fan_error = -1;
    const bool forced =
        cx.options.split && cx.options.split->count(subpatch_key(cx.patch_index, r));
    const bool planar = criteria_accept(cx, b, r, centre, V, forced, fan_error);
    const bool can_u = r.s1 - r.s0 > 1, can_v = r.t1 - r.t0 > 1;
    // Past the budget (SubdivisionOptions::leaves_left) the pass is refused:
    // stop splitting so that it ends at once.
    std::atomic<std::int64_t>* const left = cx.options.leaves_left;
    const bool spent = left && left->load(std::memory_order_relaxed) < 0;
    if (planar || spent || depth >= cx.options.max_depth || (!can_u && !can_v)) {
        Subpatch leaf;
        leaf.patch = cx.patch_index;
        leaf.node = id;
        leaf.rect = r;
        leaf.depth = depth;
        leaf.planar = planar;
        leaf.corners = V;
        leaf.centre = centre;
        leaf.fan_error = std::max(fan_error, 0.0);
        add_leaf(cx, leaf);
        return id;
    }
    const bool in_u = halve_in_u(cx, b, r, fan_error, forced);
    std::array<BezierPatch, 2>& half = cx.half(depth);
    BezierPatch &lo = half[0], &hi = half[1];
    ParamRect rlo = r, rhi = r;
    if (in_u) {
        split_u(b, 0.5, lo, hi);
        const int m = r.s0 + (r.s1 - r.s0) / 2;
        rlo.s1 = m;
        rhi.s0 = m;
    } else {
        split_v(b, 0.5, lo, hi);
        const int m = r.t0 + (r.t1 - r.t0) / 2;
        rlo.t1 = m;
        rhi.t0 = m;
    }
    const int a = recurse(cx, lo, rlo, depth + 1);
    const int c = recurse(cx, hi, rhi, depth + 1);
    if (nodes) {
        PatchNode& n = cx.trees.nodes[id];
        n.split = in_u ? 0 : 1;
        n.child[0] = a;
        n.child[1] = c;
    }
    return id;
}

} // namespace

std::uint64_t subpatch_key(int patch, const ParamRect& r) {
    std::uint64_t h = 0x9E3779B97F4A7C15ull;
    for (int x : {patch, r.s0, r.s1, r.t0, r.t1})
        h = (h ^ static_cast<std::uint32_t>(x)) * 0xBF58476D1CE4E5B9ull + (h >> 29);
    return h;
}

int subdivide(const BezierPatch& patch, int patch_index, const SubdivisionOptions& options,
              PatchTrees& trees, std::vector<Subpatch>& out) {
    SEAMLESS_CHECK(options.max_depth >= 0, "negative max_depth");
    // Per thread; emptied when the degrees change, so that every entry a
    // split does not write is as in a fresh BezierPatch.
    thread_local std::deque<std::array<BezierPatch, 2>> halves;
    thread_local int halves_p = -1, halves_q = -1;
    if (patch.p != halves_p || patch.q != halves_q) {
        halves.clear();
        halves_p = patch.p;
        halves_q = patch.q;
    }
    Context cx{patch_index, options, trees, out, halves};
    const int root = recurse(cx, patch, ParamRect{}, 0);
    if (options.leaves_left && cx.unflushed > 0)
        options.leaves_left->fetch_sub(cx.unflushed, std::memory_order_relaxed);
    return root;
}

} // namespace seamless
