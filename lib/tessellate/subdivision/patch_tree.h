// SPDX-License-Identifier: MIT
// Binary patch trees (paper Proposition 11, remark 2 and Fig. 2): per Bezier
// patch one binary tree whose root is the patch, whose inner nodes' sons are the
// two halves of a subdivision step and whose leaves are triangles (the fan of a
// planar subpatch hangs below it as a balanced binary subtree). Each node keeps
// the coordinate hull of its subpatch's control points and of its triangles, so
// a ray cluster is compared with a node's hull before its sons are visited
// (remark 1). All trees share one flat node array; sons have larger indices
// than their father.
#pragma once

#include <seamless/base/check.h>
#include <seamless/base/vec.h>

#include <vector>

namespace seamless {

struct PatchNode {
    // Hull of the subpatch's control points: holds the exact subpatch (convex
    // hull property). Empty for the triangle nodes below a planar subpatch.
    Box3 control_hull;
    // Hull of every triangle below the node (interval hull of the sons' hulls).
    Box3 triangle_hull;
    int child[2] = {-1, -1};
    int triangle = -1; // triangle index (into TriangleMesh::triangles) at a leaf
    int subpatch = -1; // index of the planar subpatch (Tessellation::subpatches) it is
    int split = -1;    // 0: split in u, 1: split in v, -1: not split
};

struct PatchTrees {
    std::vector<PatchNode> nodes;
    std::vector<int> roots; // one per Bezier patch, in bezier_patches(model) order

    // Largest depth of any tree, the stack size a traversal needs.
    int depth = 0;
};

// Remark 2: starting with the roots, descends into every node whose
// triangle_hull satisfies `box_pred` and calls visit(triangle) at the triangles
// reached. No allocation: a fixed stack, sized by the trees' depth.
template <class BoxPred, class Visit>
void visit_candidate_triangles(const PatchTrees& trees, BoxPred&& box_pred, Visit&& visit) {
    constexpr int kStack = 256;
    SEAMLESS_CHECK(trees.depth < kStack - 2, "patch trees deeper than the visit's stack");
    int stack[kStack];
    for (int root : trees.roots) {
        int top = 0;
        stack[top++] = root;
        while (top > 0) {
            const PatchNode& n = trees.nodes[stack[--top]];
            if (n.triangle_hull.empty() || !box_pred(n.triangle_hull)) continue;
            if (n.triangle >= 0) visit(n.triangle);
            for (int c : n.child)
                if (c >= 0) stack[top++] = c;
        }
    }
}

// Recomputes the triangle_hull of nodes [begin, end) bottom-up from the
// triangles' corners; sons outside the range must be up to date. Ranges whose
// sons lie inside them (one patch's nodes, one fan's subtree) can be updated
// in parallel.
template <class TriangleBox>
void update_triangle_hulls(PatchTrees& trees, int begin, int end, TriangleBox&& triangle_box) {
    for (int i = end - 1; i >= begin; --i) {
        PatchNode& n = trees.nodes[i];
        n.triangle_hull = Box3{};
        if (n.triangle >= 0) n.triangle_hull.extend(triangle_box(n.triangle));
        for (int c : n.child) {
            if (c < 0) continue;
            SEAMLESS_DCHECK(c > i, "a child node stored before its parent");
            n.triangle_hull.extend(trees.nodes[c].triangle_hull);
        }
    }
}

// Recomputes every triangle_hull bottom-up from the triangles' corners.
template <class TriangleBox>
void update_triangle_hulls(PatchTrees& trees, TriangleBox&& triangle_box) {
    update_triangle_hulls(trees, 0, static_cast<int>(trees.nodes.size()), triangle_box);
}

// Nodes that attach_triangles adds for `count` triangles.
constexpr int attached_nodes(int count) {
    return count >= 2 ? 2 * count - 2 : 0;
}

// Hangs the triangles [first, first + count) below node `at` as a balanced
// binary subtree; returns the depth added below `at`.
int attach_triangles(PatchTrees& trees, int at, int first, int count);

// Same subtree, written into the nodes [node0, node0 + attached_nodes(count))
// that already exist (so that fans can be attached in parallel).
int attach_triangles_at(PatchTrees& trees, int at, int first, int count, int node0);

} // namespace seamless
