// SPDX-License-Identifier: MIT
#include <seamless/base/check.h>
#include <seamless/tessellate/trimmed/face_trees.h>

#include <algorithm>
#include <numeric>

namespace seamless {
namespace {

class TreeBuilder {
  public:
    TreeBuilder(const TriangleMesh& mesh, PatchTrees& trees) : mesh_(mesh), trees_(trees) {}

    // The tree of the triangles order_[first, last), count >= 1; returns its root.
    int build(int first, int last, int level) {
        const int id = static_cast<int>(trees_.nodes.size());
        trees_.nodes.emplace_back();
        trees_.depth = std::max(trees_.depth, level);
        Box3 hull, centres;
        for (int k = first; k < last; ++k) {
            hull.extend(box(order_[k]));
            centres.extend(centre(order_[k]));
        }
        trees_.nodes[id].triangle_hull = hull;
        if (last - first == 1) {
            trees_.nodes[id].triangle = order_[first];
            return id;
        }
        const Vec3 extent = centres.hi - centres.lo;
        const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0
                         : extent.y >= extent.z                       ? 1
                                                                      : 2;
        const int mid = first + (last - first) / 2;
        // Ties by triangle index: the tree is the same on every run.
        std::nth_element(order_.begin() + first, order_.begin() + mid, order_.begin() + last,
                         [&](int a, int b) {
                             const double ca = centre(a)[axis], cb = centre(b)[axis];
                             return ca < cb || (ca == cb && a < b);
                         });
        const int a = build(first, mid, level + 1);
        const int b = build(mid, last, level + 1);
        trees_.nodes[id].child[0] = a;
        trees_.nodes[id].child[1] = b;
        return id;
    }

    void add_face(int first, int last) {
        order_.resize(last - first);
        std::iota(order_.begin(), order_.end(), first);
        if (first == last) {
            trees_.roots.push_back(static_cast<int>(trees_.nodes.size()));
            trees_.nodes.emplace_back();
            return;
        }
        trees_.roots.push_back(build(0, last - first, 0));
    }

  private:
    Box3 box(int t) const {
        Box3 b;
        for (int v : mesh_.triangles[t]) b.extend(mesh_.positions[v]);
        return b;
    }
    Vec3 centre(int t) const {
        const auto& tri = mesh_.triangles[t];
        return (mesh_.positions[tri[0]] + mesh_.positions[tri[1]] + mesh_.positions[tri[2]]) / 3.0;
    }

    const TriangleMesh& mesh_;
    PatchTrees& trees_;
    std::vector<int> order_;
};

} // namespace

PatchTrees face_trees(const TriangleMesh& mesh, const std::vector<int>& face_first) {
    SEAMLESS_CHECK(!face_first.empty() && face_first.back() == mesh.triangle_count(),
                   "face_first must end at the mesh's triangle count");
    PatchTrees trees;
    trees.nodes.reserve(2 * static_cast<size_t>(mesh.triangle_count()) + face_first.size());
    TreeBuilder builder(mesh, trees);
    for (size_t f = 0; f + 1 < face_first.size(); ++f)
        builder.add_face(face_first[f], face_first[f + 1]);
    return trees;
}

} // namespace seamless
