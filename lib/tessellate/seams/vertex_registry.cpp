// SPDX-License-Identifier: MIT
// The vertex registry (shared_edges.h): one vertex per key, placed at its
// exact surface point or, crack-free with straight segments, on the straight
// segment of the subpatch side holding it (Fig. 3).
#include <seamless/base/check.h>
#include <seamless/spline/surface_point.h>
#include <seamless/tessellate/seams/edge_lines.h>

namespace seamless {
namespace {

// The corners (BezierPatch::corner) at the ends of edges 0..3, each edge by
// increasing s or t (shared_edges.h).
constexpr int kEdgeCorners[4][2] = {{0, 1}, {1, 2}, {3, 2}, {0, 3}};

} // namespace

VertexKey vertex_key(const BoundaryMatch& m, int patch, int s, int t) {
    const int N = kParamOne;
    int corner = -1;
    if (s == 0 && t == 0)
        corner = 0;
    else if (s == N && t == 0)
        corner = 1;
    else if (s == N && t == N)
        corner = 2;
    else if (s == 0 && t == N)
        corner = 3;
    if (corner >= 0) return {0, m.corner_root[4 * patch + corner], 0, 0};
    int e = -1, x = 0;
    if (t == 0)
        e = 0, x = s;
    else if (s == N)
        e = 1, x = t;
    else if (t == N)
        e = 2, x = s;
    else if (s == 0)
        e = 3, x = t;
    if (e < 0) return {2, patch, s, t};
    const int pe = 4 * patch + e;
    if (m.collapsed[pe]) return {0, m.corner_root[4 * patch + kEdgeCorners[e][0]], 0, 0};
    return {1, m.edge_group[pe], m.edge_reversed[pe] ? N - x : x, 0};
}

Vec3 exact_position(const std::vector<BezierPatch>& patches, const BoundaryMatch& m,
                    VertexKey key) {
    if (key.kind == 0) return patches[key.id / 4].corner(key.id % 4);
    if (key.kind == 1) {
        // Also every seam vertex (edge_graph.h): its line has one side only.
        const int ref = m.group_ref[key.id];
        int gs = 0, gt = 0;
        edge_grid_point(ref % 4, key.a, gs, gt);
        return exact_point(patches[ref / 4], param_of(gs), param_of(gt));
    }
    return exact_point(patches[key.id], param_of(key.a), param_of(key.b));
}

VertexKey canonical_key(const VertexRegistry& vr, VertexKey key) {
    if (vr.alias && !vr.alias->empty()) {
        auto a = vr.alias->find(key);
        if (a != vr.alias->end()) return a->second;
    }
    return key;
}

int vertex_at(VertexRegistry& vr, int patch, int s, int t) {
    return vertex_of(vr, vertex_key(*vr.match, patch, s, t));
}

namespace {

// Crack-free with straight segments: the point on the straight segment of
// the subpatch side holding `key` strictly inside (Fig. 3, Q0 = (Q1 + Q2) / 2
// recursively), placing the segment's ends first; false when no side holds it.
bool straight_point(VertexRegistry& vr, VertexKey key, Vec3& p) {
    if (!vr.crack_free || !vr.straight_segments) return false;
    if (key.kind == 1) {
        // A point of global edge g, on the reference patch's side.
        const LineSegment* seg = containing(*vr.edges, key.id, key.a);
        if (!seg) return false;
        const int ref = vr.match->group_ref[key.id];
        int gs = 0, gt = 0;
        edge_grid_point(ref % 4, seg->a, gs, gt);
        const int ia = vertex_at(vr, ref / 4, gs, gt);
        edge_grid_point(ref % 4, seg->b, gs, gt);
        const int ib = vertex_at(vr, ref / 4, gs, gt);
        p = lerp(vr.positions[ia], vr.positions[ib],
                 static_cast<double>(key.a - seg->a) / (seg->b - seg->a));
        return true;
    }
    if (key.kind != 2) return false;
    const int patch = key.id, s = key.a, t = key.b;
    // At most one subpatch side holds a grid point strictly inside.
    const LineSegment* seg = nullptr;
    bool along_s = true;
    const int h = find_interior_line(*vr.edges, line_key(patch, 0, t));
    if (h >= 0) seg = containing(*vr.edges, h, s);
    if (!seg) {
        const int v = find_interior_line(*vr.edges, line_key(patch, 1, s));
        if (v >= 0) seg = containing(*vr.edges, v, t), along_s = false;
    }
    if (!seg) return false;
    const int ia = along_s ? vertex_at(vr, patch, seg->a, t) : vertex_at(vr, patch, s, seg->a);
    const int ib = along_s ? vertex_at(vr, patch, seg->b, t) : vertex_at(vr, patch, s, seg->b);
    const int x = along_s ? s : t;
    p = lerp(vr.positions[ia], vr.positions[ib],
             static_cast<double>(x - seg->a) / (seg->b - seg->a));
    return true;
}

} // namespace

int vertex_of(VertexRegistry& vr, VertexKey key) {
    key = canonical_key(vr, key);
    auto [it, fresh] = vr.index.try_emplace(key, static_cast<int>(vr.positions.size()));
    const int id = it->second;
    if (!fresh) {
        SEAMLESS_CHECK(vr.placed[id], "crack-free placement must not be cyclic");
        return id;
    }
    vr.positions.emplace_back();
    vr.placed.push_back(0);
    Vec3 p;
    if (!straight_point(vr, key, p)) p = exact_position(*vr.patches, *vr.match, key);
    vr.positions[id] = p;
    vr.placed[id] = 1;
    return id;
}

} // namespace seamless
