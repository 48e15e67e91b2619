// SPDX-License-Identifier: MIT
#include <seamless/mesh/check/defect_faces.h>

#include <algorithm>
#include <map>
#include <utility>

namespace seamless {
namespace {

bool has_ids(const TriangleMesh& mesh) {
    return !mesh.triangles.empty() && mesh.triangle_face.size() == mesh.triangles.size() &&
           mesh.triangle_part.size() == mesh.triangles.size();
}

// (part, face) of triangle t.
std::pair<int, int> face_key(const TriangleMesh& mesh, int t) {
    return {mesh.triangle_part[t], mesh.triangle_face[t]};
}

} // namespace

std::vector<std::vector<int>> defect_triangles(const CheckReport& r) {
    std::vector<std::vector<int>> out;
    for (const BorderLoop& l : r.border_loops) out.push_back(l.triangles);
    for (const Crack& c : r.cracks) out.push_back({c.triangle, c.other_triangle});
    for (const TJunction& j : r.t_junctions) out.push_back({j.triangle});
    for (const TriangleDefect& d : r.degenerate_triangles) out.push_back({d.triangle});
    for (const auto* pairs :
         {&r.duplicated_triangles, &r.inconsistent_orientation, &r.self_intersections})
        for (const TrianglePair& p : *pairs) out.push_back({p.t0, p.t1});
    return out;
}

std::vector<DefectFace> defect_faces(const TriangleMesh& mesh, const CheckReport& r) {
    if (!has_ids(mesh)) return {};
    std::map<std::pair<int, int>, DefectFace> faces;
    std::vector<std::pair<int, int>> keys;
    for (const std::vector<int>& tris : defect_triangles(r)) {
        keys.clear();
        for (int t : tris) {
            if (t < 0 || t >= mesh.triangle_count()) continue;
            keys.push_back(face_key(mesh, t));
            faces.try_emplace(keys.back(), DefectFace{keys.back().first, keys.back().second, 0, t});
        }
        std::sort(keys.begin(), keys.end());
        keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
        for (const auto& k : keys) ++faces[k].defects;
    }
    std::vector<DefectFace> out;
    for (const auto& entry : faces) out.push_back(entry.second);
    return out;
}

std::string triangle_place(const TriangleMesh& mesh, int t) {
    if (!has_ids(mesh) || t < 0 || t >= mesh.triangle_count()) return "";
    const auto [part, face] = face_key(mesh, t);
    std::string s = face >= 0 ? "face " + std::to_string(face) : "no face";
    if (part < 0) return s;
    s += " of part " + std::to_string(part);
    if (part < static_cast<int>(mesh.part_names.size())) s += " (" + mesh.part_names[part] + ")";
    return s;
}

std::string places(const TriangleMesh& mesh, const std::vector<int>& triangles) {
    std::vector<std::pair<std::pair<int, int>, int>> seen; // (part, face), a triangle on it
    for (int t : triangles)
        if (has_ids(mesh) && t >= 0 && t < mesh.triangle_count())
            seen.push_back({face_key(mesh, t), t});
    std::sort(seen.begin(), seen.end());
    std::string s;
    for (size_t k = 0; k < seen.size(); ++k) {
        if (k > 0 && seen[k].first == seen[k - 1].first) continue;
        if (!s.empty()) s += ", ";
        s += triangle_place(mesh, seen[k].second);
    }
    return s;
}

} // namespace seamless
