// SPDX-License-Identifier: MIT
#include <seamless/mesh/check/shell_measures.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Surface_mesh.h>

#include <unordered_map>

namespace seamless {

void measure_closed_shells(const WeldedMesh& mesh, Shells& S) {
    using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
    using SurfaceMesh = CGAL::Surface_mesh<Point>;
    const auto& P = mesh.positions;
    const auto& T = mesh.triangles;
    const int n = static_cast<int>(S.shells.size());
    std::vector<std::vector<int>> tris(n);
    for (int t = 0; t < static_cast<int>(T.size()); ++t) tris[S.triangle_shell[t]].push_back(t);
    for (int c = 0; c < n; ++c) {
        ComponentReport& C = S.shells[c];
        if (!C.closed) continue;
        C.euler = C.vertices - C.edges + C.triangles;
        if (S.manifold_bad[c]) continue;
        if (*C.euler % 2 == 0) C.genus = (2 - *C.euler) / 2;
        SurfaceMesh sm;
        std::unordered_map<int, SurfaceMesh::Vertex_index> vid;
        bool ok = true;
        for (int t : tris[c]) {
            std::array<SurfaceMesh::Vertex_index, 3> vs;
            for (int k = 0; k < 3; ++k) {
                auto [it, inserted] = vid.try_emplace(T[t][k]);
                if (inserted)
                    it->second = sm.add_vertex(Point(P[T[t][k]].x, P[T[t][k]].y, P[T[t][k]].z));
                vs[k] = it->second;
            }
            if (sm.add_face(vs[0], vs[1], vs[2]) == SurfaceMesh::null_face()) {
                ok = false;
                break;
            }
        }
        if (!ok || !CGAL::is_closed(sm)) continue;
        C.volume = CGAL::Polygon_mesh_processing::volume(sm);
        C.outward = CGAL::Polygon_mesh_processing::is_outward_oriented(sm);
    }
}

} // namespace seamless
