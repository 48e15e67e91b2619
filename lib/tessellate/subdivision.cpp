// SPDX-License-Identifier: MIT
#include <seamless/tessellate/error_bound.h>
#include <seamless/tessellate/planarity.h>
#include <seamless/tessellate/subdivision.h>

#include <algorithm>
#include <cassert>

namespace seamless {
namespace {

struct Context {
    int patch_index;
    const SubdivisionOptions& options;
    PatchTrees& trees;
    std::vector<Subpatch>& out;
};

// True to split in u (s), false for v (t).
bool split_in_u(const BezierPatch& b) {
    const double fu = flatness_u(b), fv = flatness_v(b);
    if (fu > 2 * fv) return true;
    if (fv > 2 * fu) return false;
    const double lu = distance(b.corner(0), b.corner(1)) + distance(b.corner(3), b.corner(2));
    const double lv = distance(b.corner(0), b.corner(3)) + distance(b.corner(1), b.corner(2));
    return lu >= lv;
}

int recurse(Context& cx, const BezierPatch& b, ParamRect r, int depth) {
    const int id = static_cast<int>(cx.trees.nodes.size());
    cx.trees.nodes.emplace_back();
    cx.trees.nodes[id].control_hull = control_box(b);
    cx.trees.depth = std::max(cx.trees.depth, depth);

    const bool planar = planarity(b).planar(cx.options.eps1, cx.options.eps2);
    // A side can only be halved while it spans more than one grid step.
    const bool can_u = r.s1 - r.s0 > 1, can_v = r.t1 - r.t0 > 1;
    if (planar || depth >= cx.options.max_depth || (!can_u && !can_v)) {
        Subpatch leaf;
        leaf.patch = cx.patch_index;
        leaf.node = id;
        leaf.rect = r;
        leaf.depth = depth;
        leaf.planar = planar;
        leaf.bilinear_error = bilinear_deviation(b);
        for (int c = 0; c < 4; ++c) leaf.corners[c] = b.corner(c);
        cx.trees.nodes[id].subpatch = static_cast<int>(cx.out.size());
        cx.out.push_back(leaf);
        return id;
    }
    bool in_u = split_in_u(b);
    if (in_u && !can_u) in_u = false;
    if (!in_u && !can_v) in_u = true;
    BezierPatch lo, hi;
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
    cx.trees.nodes[id].split = in_u ? 0 : 1;
    const int a = recurse(cx, lo, rlo, depth + 1);
    const int c = recurse(cx, hi, rhi, depth + 1);
    cx.trees.nodes[id].child[0] = a;
    cx.trees.nodes[id].child[1] = c;
    return id;
}

} // namespace

int subdivide(const BezierPatch& patch, int patch_index, const SubdivisionOptions& options,
              PatchTrees& trees, std::vector<Subpatch>& out) {
    assert(options.max_depth >= 0);
    Context cx{patch_index, options, trees, out};
    return recurse(cx, patch, ParamRect{}, 0);
}

} // namespace seamless
