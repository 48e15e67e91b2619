// SPDX-License-Identifier: MIT
// The binary patch trees (Proposition 11, remark 2) laid out for the hull
// comparisons of secondary rays and clusters: each patch's nodes in the order
// in which the depth-first visit of the trees meets them (a node, then the
// subtree of its son 1, then that of its son 0), each with its triangle hull,
// its triangle and the index past its subtree. A visit walks the array
// forwards and jumps past a subtree whose hull the predicate rejects, so it
// compares the same hulls and meets the same triangles in the same order as
// the stack visit over PatchTrees, reading less than half the memory (no
// control hull) in order.
#pragma once

#include <seamless/base/vec.h>
#include <seamless/tessellate/subdivision/patch_tree.h>

#include <vector>

namespace seamless {

struct FlatNode {
    Box3 hull;         // PatchNode::triangle_hull, never empty
    int triangle = -1; // a leaf's triangle, or -1
    int next = 0;      // index past the node's subtree
};

struct FlatPatchTrees {
    std::vector<FlatNode> nodes;
    // Patch p (the order of PatchTrees::roots) owns nodes [first[p], first[p + 1]).
    std::vector<int> first;
};

// Nodes with an empty triangle hull are left out with their subtrees (a visit
// never enters them).
FlatPatchTrees flatten_patch_trees(const PatchTrees& trees);

// The nodes of patch p whose hull, and those of the nodes above, satisfy
// box_pred, in the stack visit's order: visit(triangle) returns true to stop
// (then true).
template <class BoxPred, class Visit>
bool visit_flat_tree(const FlatPatchTrees& f, int p, BoxPred&& box_pred, Visit&& visit) {
    const FlatNode* nodes = f.nodes.data();
    int i = f.first[p];
    const int end = f.first[p + 1];
    while (i < end) {
        const FlatNode& n = nodes[i];
        if (!box_pred(n.hull)) {
            i = n.next;
            continue;
        }
        if (n.triangle >= 0 && visit(n.triangle)) return true;
        ++i;
    }
    return false;
}

// visit_candidate_triangles (patch_tree.h) on the flat layout: every patch's
// tree in the order of the roots, each triangle reached passed to visit.
template <class BoxPred, class Visit>
void visit_flat_candidates(const FlatPatchTrees& f, BoxPred&& box_pred, Visit&& visit) {
    const int patches = static_cast<int>(f.first.size()) - 1;
    for (int p = 0; p < patches; ++p)
        visit_flat_tree(f, p, box_pred, [&](int t) {
            visit(t);
            return false;
        });
}

} // namespace seamless
