// SPDX-License-Identifier: MIT
#include <seamless/tessellate/trimmed/brep_mesh.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace seamless {

namespace {

// Two faces meeting along an edge whose discretised pcurve bends into both
// of them (in (u,v), by a rounding where re-splitting crowded its points)
// each keep the ear of three consecutive edge points: the same triangle,
// once each way round, a fin of no volume. Both go: the chord between the
// ear's outer points then joins the faces' other triangles, the edge's
// middle point is left unused, and the mesh stays closed and manifold.
void remove_fins(TriangleMesh& m) {
    // Triangles by their sorted corners, in one sorted array (no node per triangle).
    std::vector<std::pair<std::array<int, 3>, int>> by_corners(m.triangles.size());
    for (int t = 0; t < m.triangle_count(); ++t) {
        std::array<int, 3> key = m.triangles[t];
        std::sort(key.begin(), key.end());
        by_corners[t] = {key, t};
    }
    std::sort(by_corners.begin(), by_corners.end());
    const auto opposite = [&](int a, int b) {
        const auto& x = m.triangles[a];
        const auto& y = m.triangles[b];
        for (int r = 0; r < 3; ++r)
            if (x[0] == y[r] && x[1] == y[(r + 2) % 3] && x[2] == y[(r + 1) % 3]) return true;
        return false;
    };
    std::vector<char> drop(m.triangles.size(), 0);
    bool any = false;
    for (size_t begin = 0, end = 0; begin < by_corners.size(); begin = end) {
        while (end < by_corners.size() && by_corners[end].first == by_corners[begin].first) ++end;
        for (size_t i = begin; i < end; ++i)
            for (size_t j = i + 1; j < end && !drop[by_corners[i].second]; ++j) {
                const int a = by_corners[i].second, b = by_corners[j].second;
                if (!drop[b] && opposite(a, b)) drop[a] = drop[b] = 1, any = true;
            }
    }
    if (!any) return;
    size_t kept = 0;
    for (size_t t = 0; t < drop.size(); ++t) {
        if (drop[t]) continue;
        m.triangles[kept] = m.triangles[t];
        m.triangle_surface[kept] = m.triangle_surface[t];
        m.corner_normals[kept] = m.corner_normals[t];
        m.corner_uvs[kept] = m.corner_uvs[t];
        ++kept;
    }
    m.triangles.resize(kept);
    m.triangle_surface.resize(kept);
    m.corner_normals.resize(kept);
    m.corner_uvs.resize(kept);
}

} // namespace

TriangleMesh brep_mesh(const Model& model, const std::vector<EdgePolyline>& lines,
                       const std::vector<FaceMesh>& meshes) {
    const BRep& brep = model.brep;
    TriangleMesh m;
    // Sized once: grown by doubling, the arrays' copies and first touches
    // of new pages were most of this step's time on large models.
    size_t points = brep.vertices.size(), triangles = 0;
    for (const EdgePolyline& line : lines) points += line.points.size();
    for (const FaceMesh& fm : meshes) {
        points += fm.domain.size() - fm.domain.boundary_points;
        triangles += fm.triangles.size();
    }
    m.positions.reserve(points);
    m.triangles.reserve(triangles);
    m.triangle_surface.reserve(triangles);
    m.corner_normals.reserve(triangles);
    m.corner_uvs.reserve(triangles);
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
    remove_fins(m);
    return m;
}

} // namespace seamless
