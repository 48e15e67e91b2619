// SPDX-License-Identifier: MIT
#include <seamless/render/pixels/pixel_lights.h>

#include <algorithm>
#include <cmath>

namespace seamless {
namespace {

// ClusterHull of ray_cluster.h for the cluster from a light L to a box of
// points, whose points are the convex hull of L and the box: its
// axis-aligned hull and two axes across its mean direction, evaluated in
// doubles (centre and radius along each axis) with a relative margin of
// 1e-12, a thousand times the few ulps such a sum can err by. Conservative
// as ClusterHull, at a fraction of its cost.
class PyramidHull {
  public:
    PyramidHull(Vec3 L, const IVec<3>& Pw) {
        Vec3 c, r;
        for (int i = 0; i < 3; ++i) {
            box_.lo[i] = std::min(L[i], Pw[i].lo());
            box_.hi[i] = std::max(L[i], Pw[i].hi());
            c[i] = Pw[i].mid();
            r[i] = Pw[i].rad();
        }
        Vec3 d = c - L;
        if (!(norm(d) > 0)) d = {0, 0, 1};
        d = normalize(d);
        const Vec3 seed = std::abs(d.x) < 0.6 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
        axis_[0] = normalize(cross(d, seed));
        axis_[1] = cross(d, axis_[0]);
        for (int k = 0; k < 2; ++k) {
            const Interval pb = project(axis_[k], c, r), pl = project(axis_[k], L, Vec3{});
            lo_[k] = std::min(pb.lo(), pl.lo());
            hi_[k] = std::max(pb.hi(), pl.hi());
        }
    }
    bool may_meet(const Box3& b) const {
        for (int i = 0; i < 3; ++i)
            if (b.hi[i] < box_.lo[i] || b.lo[i] > box_.hi[i]) return false;
        const Vec3 c = 0.5 * (b.lo + b.hi), r = 0.5 * (b.hi - b.lo);
        for (int k = 0; k < 2; ++k) {
            const Interval p = project(axis_[k], c, r);
            if (p.hi() < lo_[k] || p.lo() > hi_[k]) return false;
        }
        return true;
    }

  private:
    // a . x over the box of centre c and radius r, widened by the margin
    // (which also covers the rounding of c and r themselves).
    static Interval project(Vec3 a, Vec3 c, Vec3 r) {
        const double m = dot(a, c);
        double rad = 0, size = 0;
        for (int i = 0; i < 3; ++i) {
            rad += std::abs(a[i]) * r[i];
            size += std::abs(a[i]) * (std::abs(c[i]) + r[i]);
        }
        const double slack = rad + 1e-12 * size;
        return {m - slack, m + slack};
    }
    Box3 box_;
    Vec3 axis_[2];
    double lo_[2], hi_[2];
};

// Whether some triangle of another patch than `skip` may meet the cluster:
// the root hierarchy's boxes, then each patch tree's triangle hulls, compared
// with the cluster's hull (remarks 1-2), then the triangles themselves
// (pyramid_may_meet_triangle; Proposition 11's contraction after it, tried,
// rejected too few triangles to pay). The patch's own tree is
// never entered: its triangles lie at the cluster's end points.
// hint: a triangle that met an earlier cluster to the same light, tried first
// (shadows are coherent); set to the one found.
bool may_block(const TriangleScene& ts, const IVec<3>& Pw, int l, Vec3 light, int skip, int& hint) {
    const PyramidHull ch(light, Pw);
    const PatchTrees& trees = ts.tess.trees;
    const auto meets = [&](int t) {
        if (!light_pyramid_may_meet(ts, l, light, Pw, t)) return false;
        hint = t;
        return true;
    };
    if (hint >= 0 && hint < ts.tess.mesh.triangle_count() && ts.triangle_patch[hint] != skip &&
        meets(hint))
        return true;
    const auto tree_may_block = [&](int p) {
        return visit_flat_tree(
            ts.flat_trees, p, [&](const Box3& b) { return ch.may_meet(b); }, meets);
    };
    const RootHierarchy& h = ts.root_hierarchy;
    if (h.nodes.empty()) {
        for (size_t p = 0; p < trees.roots.size(); ++p)
            if (static_cast<int>(p) != skip && tree_may_block(static_cast<int>(p))) return true;
        return false;
    }
    return visit_roots(
        h, skip, [&](const Box3& b) { return ch.may_meet(b); }, tree_may_block);
}

} // namespace

void lights_reaching_box(const Scene& scene, const TriangleScene& ts, const IVec<3>& Pw, int patch,
                         char* lit, int* hints) {
    for (size_t l = 0; l < scene.lights.size(); ++l) {
        const Light& light = scene.lights[l];
        lit[l] = 0;
        if (!light.on()) continue;
        lit[l] = may_block(ts, Pw, static_cast<int>(l), light.position, patch, hints[l]) ? 0 : 1;
    }
}

} // namespace seamless
