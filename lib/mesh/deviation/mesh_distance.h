// SPDX-License-Identifier: MIT
// Distance from points to a triangle mesh: CGAL's AABB tree of its triangles
// (kept inside mesh_distance.cpp), built once, then queried from any number
// of threads at once.
#pragma once

#include <seamless/base/triangle_mesh.h>

#include <memory>

namespace seamless {

class MeshDistance {
  public:
    // Triangles with a repeated vertex index are left out.
    explicit MeshDistance(const TriangleMesh& mesh);
    ~MeshDistance();
    MeshDistance(const MeshDistance&) = delete;
    MeshDistance& operator=(const MeshDistance&) = delete;

    bool empty() const;
    // Distance to the closest point of the mesh; only when !empty().
    double operator()(Vec3 p) const;

  private:
    struct Tree;
    std::unique_ptr<Tree> tree_;
};

} // namespace seamless
