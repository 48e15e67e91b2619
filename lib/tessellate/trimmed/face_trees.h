// SPDX-License-Identifier: MIT
// Binary trees over the triangles of trimmed faces, for the renderer: the
// trimmed pipeline has no subdivision tree of Bezier patches to hang its
// triangles below (Proposition 11, remark 2), so each face gets a tree of
// median splits of its triangles' centres along the widest axis, with the
// triangle hulls remark 1 needs. One root per face, in face order, with the
// same node layout as PatchTrees (sons after their father).
#pragma once

#include <seamless/base/triangle_mesh.h>
#include <seamless/tessellate/subdivision/patch_tree.h>

#include <vector>

namespace seamless {

// face_first[f] .. face_first[f + 1] are face f's triangles in `mesh`
// (face_first.size() = faces + 1). A face without triangles gets a root with
// an empty hull.
PatchTrees face_trees(const TriangleMesh& mesh, const std::vector<int>& face_first);

} // namespace seamless
