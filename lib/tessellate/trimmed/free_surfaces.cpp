// SPDX-License-Identifier: MIT
#include <seamless/base/check.h>
#include <seamless/tessellate/trimmed/free_surfaces.h>

#include <algorithm>

namespace seamless {

std::vector<int> free_surfaces(const Model& m) {
    std::vector<char> used(m.surfaces.size(), 0);
    for (const BRepFace& f : m.brep.faces)
        if (f.surface >= 0 && f.surface < static_cast<int>(used.size())) used[f.surface] = 1;
    std::vector<int> free;
    for (size_t s = 0; s < used.size(); ++s)
        if (!used[s]) free.push_back(static_cast<int>(s));
    return free;
}

Model free_surface_model(const Model& m, const std::vector<int>& surfaces) {
    Model part;
    part.source = m.source;
    for (int s : surfaces) {
        part.surfaces.push_back(m.surfaces[s]);
        if (!m.origins.empty()) part.origins.push_back(m.origins[s]);
    }
    return part;
}

void append_tessellation(Tessellation& into, const Tessellation& part,
                         const std::vector<int>& surfaces) {
    TriangleMesh& a = into.mesh;
    const TriangleMesh& b = part.mesh;
    const int v0 = a.vertex_count(), t0 = a.triangle_count();
    a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
    for (auto tri : b.triangles) {
        for (int& v : tri) v += v0;
        a.triangles.push_back(tri);
    }
    for (int s : b.triangle_surface) {
        SEAMLESS_CHECK(s >= 0 && s < static_cast<int>(surfaces.size()),
                       "a free surface's triangle names a surface outside its model");
        a.triangle_surface.push_back(surfaces[s]);
    }
    // Attributes present on one side only cannot be joined: drop them.
    auto join = [&](auto& x, const auto& y) {
        if (x.size() == static_cast<size_t>(t0) && y.size() == b.triangles.size())
            x.insert(x.end(), y.begin(), y.end());
        else
            x.clear();
    };
    join(a.corner_normals, b.corner_normals);
    join(a.corner_uvs, b.corner_uvs);
    const int n0 = static_cast<int>(into.trees.nodes.size());
    for (PatchNode n : part.trees.nodes) {
        for (int& c : n.child)
            if (c >= 0) c += n0;
        if (n.triangle >= 0) n.triangle += t0;
        into.trees.nodes.push_back(n);
    }
    for (int r : part.trees.roots) into.trees.roots.push_back(r + n0);
    into.trees.depth = std::max(into.trees.depth, part.trees.depth);
    for (Subpatch sp : part.subpatches) {
        sp.first_triangle += t0;
        if (sp.node >= 0) sp.node += n0;
        into.subpatches.push_back(sp);
    }
    TessellationStats& s = into.stats;
    s.surfaces += part.stats.surfaces;
    s.patches += part.stats.patches;
    s.subpatches += part.stats.subpatches;
    s.triangles = a.triangle_count();
    s.vertices = a.vertex_count();
    s.max_error_bound = std::max(s.max_error_bound, part.stats.max_error_bound);
}

} // namespace seamless
