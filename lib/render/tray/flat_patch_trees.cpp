// SPDX-License-Identifier: MIT
#include <seamless/render/tray/flat_patch_trees.h>

namespace seamless {
namespace {

// Appends node k's subtree in the stack visit's order (it pops son 1 first).
void append(const PatchTrees& trees, int k, std::vector<FlatNode>& out) {
    const PatchNode& n = trees.nodes[k];
    if (n.triangle_hull.empty()) return;
    const size_t at = out.size();
    out.push_back({n.triangle_hull, n.triangle, 0});
    for (int s = 1; s >= 0; --s)
        if (n.child[s] >= 0) append(trees, n.child[s], out);
    out[at].next = static_cast<int>(out.size());
}

} // namespace

FlatPatchTrees flatten_patch_trees(const PatchTrees& trees) {
    FlatPatchTrees f;
    f.nodes.reserve(trees.nodes.size());
    f.first.reserve(trees.roots.size() + 1);
    for (int root : trees.roots) {
        f.first.push_back(static_cast<int>(f.nodes.size()));
        append(trees, root, f.nodes);
    }
    f.first.push_back(static_cast<int>(f.nodes.size()));
    return f;
}

} // namespace seamless
