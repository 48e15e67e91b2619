// SPDX-License-Identifier: MIT
// CGAL only here: an AABB tree of the triangles for the closest-point queries.
#include <seamless/mesh/deviation/mesh_distance.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <cmath>
#include <vector>

namespace seamless {
namespace {

using K = CGAL::Simple_cartesian<double>;
using Triangle = K::Triangle_3;
using Primitive = CGAL::AABB_triangle_primitive<K, std::vector<Triangle>::const_iterator>;
using AabbTree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

} // namespace

struct MeshDistance::Tree {
    std::vector<Triangle> triangles;
    AabbTree tree;
};

MeshDistance::MeshDistance(const TriangleMesh& mesh) : tree_(std::make_unique<Tree>()) {
    std::vector<Triangle>& triangles = tree_->triangles;
    triangles.reserve(mesh.triangles.size());
    for (const auto& f : mesh.triangles) {
        if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2]) continue;
        const Vec3 a = mesh.positions[f[0]], b = mesh.positions[f[1]], c = mesh.positions[f[2]];
        triangles.emplace_back(K::Point_3(a.x, a.y, a.z), K::Point_3(b.x, b.y, b.z),
                               K::Point_3(c.x, c.y, c.z));
    }
    if (triangles.empty()) return;
    tree_->tree.insert(triangles.begin(), triangles.end());
    tree_->tree.build();
    // Built before the queries: they may come from several threads.
    tree_->tree.accelerate_distance_queries();
}

MeshDistance::~MeshDistance() = default;

bool MeshDistance::empty() const {
    return tree_->triangles.empty();
}

double MeshDistance::operator()(Vec3 p) const {
    return std::sqrt(tree_->tree.squared_distance(K::Point_3(p.x, p.y, p.z)));
}

} // namespace seamless
