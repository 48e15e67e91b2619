// SPDX-License-Identifier: MIT
#include <seamless/tessellate/trimmed/brep_mesh.h>

namespace seamless {

TriangleMesh brep_mesh(const Model& model, const std::vector<EdgePolyline>& lines,
                       const std::vector<FaceMesh>& meshes) {
    const BRep& brep = model.brep;
    TriangleMesh m;
    for (const BRepVertex& v : brep.vertices) m.positions.push_back(v.point);
    std::vector<int> edge_first(brep.edges.size(), 0); // mesh index of point 1 of each edge
    for (size_t e = 0; e < brep.edges.size(); ++e) {
        edge_first[e] = m.vertex_count();
        if (brep.edges[e].degenerate()) continue;
        const std::vector<Vec3>& p = lines[e].points;
        for (size_t k = 1; k + 1 < p.size(); ++k) m.positions.push_back(p[k]);
    }
    for (const BSplineSurface& s : model.surfaces) m.surface_names.push_back(s.name);
    std::vector<int> index; // per domain point of one face
    for (size_t f = 0; f < meshes.size(); ++f) {
        const FaceMesh& fm = meshes[f];
        if (fm.failed) continue;
        const FaceDomain& d = fm.domain;
        index.assign(d.size(), -1);
        for (int i = 0; i < d.size(); ++i) {
            const std::int64_t key = d.keys[i];
            if (key < 0) {
                index[i] = m.vertex_count();
                m.positions.push_back(d.points[i]);
            } else if (is_vertex_key(key)) {
                index[i] = static_cast<int>(key);
            } else {
                index[i] = edge_first[(key >> 32) - 1] + static_cast<int>(key & 0xffffffff) - 1;
            }
        }
        const int surface = brep.faces[f].surface;
        for (size_t t = 0; t < fm.triangles.size(); ++t) {
            const auto& c = fm.triangles[t];
            m.triangles.push_back({index[c[0]], index[c[1]], index[c[2]]});
            m.triangle_surface.push_back(surface);
            m.corner_normals.push_back(fm.normals[t]);
            std::array<std::array<double, 2>, 3> uv;
            for (int k = 0; k < 3; ++k) uv[k] = {d.uv[c[k]].x, d.uv[c[k]].y};
            m.corner_uvs.push_back(uv);
        }
    }
    return m;
}

} // namespace seamless
