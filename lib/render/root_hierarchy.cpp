// SPDX-License-Identifier: MIT
#include <seamless/render/root_hierarchy.h>

#include <algorithm>

namespace seamless {
namespace {

struct Builder {
    const PatchTrees& trees;
    std::vector<RootNode>& nodes;
    std::vector<Vec3> centre; // per patch

    // Node for patches [first, last); returns its index and its depth in `depth`.
    int build(int* first, int* last, int& depth) {
        const int at = static_cast<int>(nodes.size());
        nodes.emplace_back();
        if (last - first == 1) {
            nodes[at].patch = *first;
            nodes[at].box = trees.nodes[trees.roots[*first]].triangle_hull;
            depth = 0;
            return at;
        }
        Box3 c;
        for (int* p = first; p != last; ++p) c.extend(centre[*p]);
        const Vec3 e = c.extent();
        const int axis = e.x >= e.y ? (e.x >= e.z ? 0 : 2) : (e.y >= e.z ? 1 : 2);
        int* mid = first + (last - first) / 2;
        std::nth_element(first, mid, last, [&](int a, int b) {
            const double ca = centre[a][axis], cb = centre[b][axis];
            return ca < cb || (ca == cb && a < b);
        });
        int d0 = 0, d1 = 0;
        const int c0 = build(first, mid, d0);
        const int c1 = build(mid, last, d1);
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
    Builder b{trees, h.nodes, std::vector<Vec3>(roots)};
    std::vector<int> patches;
    for (int r = 0; r < roots; ++r) {
        const Box3& box = trees.nodes[trees.roots[r]].triangle_hull;
        if (box.empty()) continue;
        b.centre[r] = 0.5 * (box.lo + box.hi);
        patches.push_back(r);
    }
    if (patches.empty()) return h;
    h.nodes.reserve(2 * patches.size());
    b.build(patches.data(), patches.data() + patches.size(), h.depth);
    return h;
}

} // namespace seamless
