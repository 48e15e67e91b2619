// SPDX-License-Identifier: MIT
#include <seamless/render/tray/root_hierarchy.h>

#include <algorithm>
#include <limits>

namespace seamless {
namespace {

// Half the surface area of a box: a ray crossing the scene meets it with a
// probability proportional to it (MacDonald and Booth 1990).
double half_area(const Box3& b) {
    const Vec3 e = b.extent();
    return e.x * e.y + e.y * e.z + e.z * e.x;
}

struct Builder {
    // Surface area splits down to this level, then median splits, so that the
    // depth (the traversal's stack) stays bounded.
    static constexpr int kSahLevels = 32;
    const PatchTrees& trees;
    std::vector<RootNode>& nodes;
    std::vector<Vec3> centre; // per patch
    std::vector<double> right_area;

    const Box3& hull(int p) const { return trees.nodes[trees.roots[p]].triangle_hull; }
    // Order by centre along axis, ties by patch index (deterministic).
    auto by_centre(int axis) const {
        return [this, axis](int a, int b) {
            const double ca = centre[a][axis], cb = centre[b][axis];
            return ca < cb || (ca == cb && a < b);
        };
    }
    void sort_along(int* first, int* last, int axis) const {
        std::sort(first, last, by_centre(axis));
    }
    // The median of the centres along their widest extent.
    int* median_split(int* first, int* last) const {
        Box3 c;
        for (int* p = first; p != last; ++p) c.extend(centre[*p]);
        const Vec3 e = c.extent();
        const int axis = e.x >= e.y ? (e.x >= e.z ? 0 : 2) : (e.y >= e.z ? 1 : 2);
        int* mid = first + (last - first) / 2;
        std::nth_element(first, mid, last, by_centre(axis));
        return mid;
    }
    // The split of the patches sorted by centre along one of the axes that
    // minimises half_area(left) * #left + half_area(right) * #right (the
    // expected number of boxes a ray enters below the node): large patches,
    // whose hulls span the scene, end up near the top instead of widening
    // every box of a median split. nullptr when no split has a finite cost.
    int* sah_split(int* first, int* last) {
        const int n = static_cast<int>(last - first);
        double best = std::numeric_limits<double>::infinity();
        int best_axis = -1, best_k = 0;
        right_area.resize(static_cast<size_t>(n));
        for (int axis = 0; axis < 3; ++axis) {
            sort_along(first, last, axis);
            Box3 b;
            for (int k = n - 1; k > 0; --k) {
                b.extend(hull(first[k]));
                right_area[static_cast<size_t>(k)] = half_area(b);
            }
            b = Box3{};
            for (int k = 1; k < n; ++k) {
                b.extend(hull(first[k - 1]));
                const double cost = half_area(b) * k + right_area[static_cast<size_t>(k)] * (n - k);
                if (cost < best) {
                    best = cost;
                    best_axis = axis;
                    best_k = k;
                }
            }
        }
        if (best_axis < 0) return nullptr;
        sort_along(first, last, best_axis);
        return first + best_k;
    }

    // Node for patches [first, last) at `level` below the top; returns its
    // index and its depth in `depth`.
    int build(int* first, int* last, int level, int& depth) {
        const int at = static_cast<int>(nodes.size());
        nodes.emplace_back();
        if (last - first == 1) {
            nodes[at].patch = *first;
            nodes[at].box = hull(*first);
            depth = 0;
            return at;
        }
        int* mid = level < kSahLevels ? sah_split(first, last) : nullptr;
        if (!mid) mid = median_split(first, last);
        int d0 = 0, d1 = 0;
        const int c0 = build(first, mid, level + 1, d0);
        const int c1 = build(mid, last, level + 1, d1);
        RootNode& n = nodes[at];
        n.child[0] = c0;
        n.child[1] = c1;
        n.box.extend(nodes[c0].box);
        n.box.extend(nodes[c1].box);
        depth = 1 + std::max(d0, d1);
        return at;
    }
};

} // namespace

RootHierarchy build_root_hierarchy(const PatchTrees& trees) {
    RootHierarchy h;
    const int roots = static_cast<int>(trees.roots.size());
    Builder b{trees, h.nodes, std::vector<Vec3>(roots), {}};
    std::vector<int> patches;
    for (int r = 0; r < roots; ++r) {
        const Box3& box = trees.nodes[trees.roots[r]].triangle_hull;
        if (box.empty()) continue;
        b.centre[r] = 0.5 * (box.lo + box.hi);
        patches.push_back(r);
    }
    if (patches.empty()) return h;
    h.nodes.reserve(2 * patches.size());
    b.build(patches.data(), patches.data() + patches.size(), 0, h.depth);
    SEAMLESS_CHECK(h.depth < RootHierarchy::kStack - 2, "the hierarchy fits visit_roots' stack");
    return h;
}

} // namespace seamless
