// SPDX-License-Identifier: MIT
#include <seamless/base/check.h>
#include <seamless/tessellate/subdivision/patch_tree.h>

#include <algorithm>

namespace seamless {
namespace {

// Node for the triangles [first, first + count), count >= 1, at index `next`
// (then advanced past its subtree, in pre-order).
int build(PatchTrees& trees, int first, int count, int& next, int& depth) {
    const int id = next++;
    trees.nodes[id] = PatchNode{};
    if (count == 1) {
        trees.nodes[id].triangle = first;
        depth = 0;
        return id;
    }
    const int half = count / 2;
    int d0 = 0, d1 = 0;
    const int a = build(trees, first, half, next, d0);
    const int b = build(trees, first + half, count - half, next, d1);
    trees.nodes[id].child[0] = a;
    trees.nodes[id].child[1] = b;
    depth = 1 + std::max(d0, d1);
    return id;
}

} // namespace

int attach_triangles(PatchTrees& trees, int at, int first, int count) {
    const int node0 = static_cast<int>(trees.nodes.size());
    trees.nodes.resize(node0 + attached_nodes(count));
    return attach_triangles_at(trees, at, first, count, node0);
}

int attach_triangles_at(PatchTrees& trees, int at, int first, int count, int node0) {
    if (count <= 0) return 0;
    if (count == 1) {
        trees.nodes[at].triangle = first;
        return 0;
    }
    const int half = count / 2;
    int d0 = 0, d1 = 0, next = node0;
    const int a = build(trees, first, half, next, d0);
    const int b = build(trees, first + half, count - half, next, d1);
    SEAMLESS_DCHECK(next == node0 + attached_nodes(count),
                    "the tree's node count is not attached_nodes");
    trees.nodes[at].child[0] = a;
    trees.nodes[at].child[1] = b;
    return 1 + std::max(d0, d1);
}

} // namespace seamless
