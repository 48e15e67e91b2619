// SPDX-License-Identifier: MIT
#include <seamless/tessellate/patch_tree.h>

#include <algorithm>

namespace seamless {
namespace {

// Node for the triangles [first, first + count), count >= 1.
int build(PatchTrees& trees, int first, int count, int& depth) {
    const int id = static_cast<int>(trees.nodes.size());
    trees.nodes.emplace_back();
    if (count == 1) {
        trees.nodes[id].triangle = first;
        depth = 0;
        return id;
    }
    const int half = count / 2;
    int d0 = 0, d1 = 0;
    const int a = build(trees, first, half, d0);
    const int b = build(trees, first + half, count - half, d1);
    trees.nodes[id].child[0] = a;
    trees.nodes[id].child[1] = b;
    depth = 1 + std::max(d0, d1);
    return id;
}

} // namespace

int attach_triangles(PatchTrees& trees, int at, int first, int count) {
    if (count <= 0) return 0;
    if (count == 1) {
        trees.nodes[at].triangle = first;
        return 0;
    }
    const int half = count / 2;
    int d0 = 0, d1 = 0;
    const int a = build(trees, first, half, d0);
    const int b = build(trees, first + half, count - half, d1);
    trees.nodes[at].child[0] = a;
    trees.nodes[at].child[1] = b;
    return 1 + std::max(d0, d1);
}

} // namespace seamless
