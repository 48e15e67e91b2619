// SPDX-License-Identifier: MIT
// A binary hierarchy over the roots of the patch trees (Proposition 11,
// remark 2, one level up): a ray first meets the hulls of groups of patches,
// so a secondary ray on a scene of many patches tests a few boxes instead of
// every root (scene 3: 103 roots, one after another before). Each node's box
// is the hull of the triangle_hull of every root below it, so a ray that
// misses it misses every triangle below (remark 1: hulls are conservative).
#pragma once

#include <seamless/base/check.h>
#include <seamless/base/vec.h>
#include <seamless/tessellate/subdivision/patch_tree.h>

#include <vector>

namespace seamless {

struct RootNode {
    Box3 box;                // hull of the triangle hulls of the roots below
    int child[2] = {-1, -1}; // inner node: both >= 0
    int patch = -1;          // leaf: the patch (index into PatchTrees::roots)
};

struct RootHierarchy {
    std::vector<RootNode> nodes; // nodes[0] the top; empty when no root has triangles
    int depth = 0;               // levels below the top, the stack a traversal needs
    // visit_roots' stack; build_root_hierarchy checks that depth fits it.
    static constexpr int kStack = 256;
};

// Surface area heuristic splits of the roots sorted by hull centre (the cut
// that minimises area x roots on both sides over the three axes; median splits
// of the centres along the widest axis below 32 levels), down to one root per
// leaf; roots without triangles are left out. Deterministic (ties by patch
// index). The shape changes only the work of a traversal, never its answers:
// nearest_hit sorts the roots met, and the other visits ask whether any meets.
RootHierarchy build_root_hierarchy(const PatchTrees& trees);

// The patches (leaves) but skip_patch whose boxes, and those of the nodes
// above them, satisfy box_pred, depth first (child 0 first): meet(patch)
// returns true to stop (then true). h must not be empty.
template <class BoxPred, class Meet>
bool visit_roots(const RootHierarchy& h, int skip_patch, BoxPred&& box_pred, Meet&& meet) {
    SEAMLESS_DCHECK(h.depth < RootHierarchy::kStack - 2, "the hierarchy fits visit_roots' stack");
    int stack[RootHierarchy::kStack];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const RootNode& n = h.nodes[stack[--top]];
        if ((n.patch >= 0 && n.patch == skip_patch) || !box_pred(n.box)) continue;
        if (n.patch >= 0) {
            if (meet(n.patch)) return true;
            continue;
        }
        stack[top++] = n.child[1];
        stack[top++] = n.child[0];
    }
    return false;
}

} // namespace seamless
