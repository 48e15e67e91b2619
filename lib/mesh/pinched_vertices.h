// SPDX-License-Identifier: MIT
// Vertices where a mesh's triangles meet in more than one fan (two shells
// touching at a point, as the teapot's handle touches its body at (-2, 0,
// 0.9)): a halfedge mesh (OpenMesh, CGAL's Surface_mesh) has one circulation
// around a vertex and cannot hold them. The conversions (openmesh.h,
// surface_mesh.h) give each fan after the first a copy of the vertex and
// record which vertex it copies, so the way back merges it again.
#pragma once

#include <seamless/base/disjoint_sets.h>
#include <seamless/base/triangle_mesh.h>

#include <array>
#include <numeric>
#include <utility>
#include <vector>

namespace seamless {

struct PinchedVertexCopies {
    // The mesh's triangles with the corners at a copy renumbered to
    // vertex_count() + j for copy j.
    std::vector<std::array<int, 3>> triangles;
    // copy_of[j]: the vertex copy j stands for.
    std::vector<int> copy_of;
};

namespace pinched_detail {

// Triangles around each vertex: those of vertex v are incident[start[v]..start[v+1]).
struct VertexTriangles {
    std::vector<int> start, incident;
    explicit VertexTriangles(const TriangleMesh& mesh) : start(mesh.vertex_count() + 1, 0) {
        for (const auto& t : mesh.triangles)
            for (int v : t) ++start[v + 1];
        std::partial_sum(start.begin(), start.end(), start.begin());
        incident.resize(start.back());
        std::vector<int> next(start.begin(), start.end() - 1);
        for (int k = 0; k < mesh.triangle_count(); ++k)
            for (int v : mesh.triangles[k]) incident[next[v]++] = k;
    }
};

} // namespace pinched_detail

// Fans are the triangles around a vertex joined across the edges they share;
// the fan of the vertex's first triangle keeps the vertex. Expects indices in
// range and distinct corners (check_convertible).
inline PinchedVertexCopies copy_pinched_vertices(const TriangleMesh& mesh) {
    PinchedVertexCopies out{mesh.triangles, {}};
    const pinched_detail::VertexTriangles around(mesh);
    std::vector<std::pair<int, int>> seen; // (other corner, first fan triangle with it)
    for (int v = 0; v < mesh.vertex_count(); ++v) {
        const int first = around.start[v], n = around.start[v + 1] - first;
        DisjointSets fans(n);
        seen.clear();
        for (int i = 0; i < n; ++i)
            for (int w : mesh.triangles[around.incident[first + i]]) {
                if (w == v) continue;
                auto it = seen.begin();
                while (it != seen.end() && it->first != w) ++it;
                if (it == seen.end())
                    seen.emplace_back(w, i);
                else
                    fans.unite(i, it->second);
            }
        std::vector<int> copy(n, -1); // per fan root: its copy's vertex index
        for (int i = 0; i < n; ++i) {
            const int root = fans.find(i);
            if (root == 0) continue;
            if (copy[root] < 0) {
                copy[root] = mesh.vertex_count() + static_cast<int>(out.copy_of.size());
                out.copy_of.push_back(v);
            }
            for (int& c : out.triangles[around.incident[first + i]])
                if (c == v) c = copy[root];
        }
    }
    return out;
}

} // namespace seamless
