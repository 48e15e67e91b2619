// SPDX-License-Identifier: MIT
// TriangleMesh <-> CGAL's Surface_mesh of Epick points (doubles), both ways,
// nothing rounded (docs/cpp.md).
//
// Opt-in and header-only: this header includes CGAL, against the rule that
// third-party libraries stay in .cpp files, because its whole point is CGAL's
// type. It adds no link dependency beyond CGAL's headers (which libseamless
// uses already); no other seamless header includes it (tests/layering checks).
//
// What maps: positions bit for bit; triangles in order, each with its first
// corner first (the face's halfedge is set to the one pointing to it); corner
// normals and corner (u,v) as the halfedge property maps "h:seamless_normal"
// (Vector_3) and "h:seamless_uv" (Point_2), per corner as a seam vertex
// needs; triangle_surface as the face property map "f:seamless_surface". A
// vertex where triangles meet in several fans (pinched_vertices.h) becomes
// one vertex per fan, the copies marked by the vertex property map
// "v:seamless_copy_of", which from_surface_mesh merges again (collect_garbage
// does not renumber that map: convert back before collecting).
// surface_names have no place in a Surface_mesh (no per-mesh properties) and
// are not carried. What does not map: an edge of three faces, or of two faces
// in the same direction, which Surface_mesh refuses: an InputError naming the
// triangle. A face of more than three corners on the way back is refused by
// name too rather than triangulated here, since a triangulation would invent
// diagonals the round trip could not give back
// (CGAL::Polygon_mesh_processing::triangulate_faces first, if that is wanted).
#pragma once

#include <seamless/mesh/convertible_mesh.h>
#include <seamless/mesh/pinched_vertices.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <string>
#include <vector>

namespace seamless {

using CgalKernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalSurfaceMesh = CGAL::Surface_mesh<CgalKernel::Point_3>;

// A vertex property map (Vertex_index): the vertex a copy of a pinched vertex
// stands for (pinched_vertices.h); invalid for every other vertex.
inline const char* const kSurfaceMeshCopyOfMap = "v:seamless_copy_of";

namespace surface_mesh_conversion {

using Halfedge = CgalSurfaceMesh::Halfedge_index;
using Face = CgalSurfaceMesh::Face_index;

// The halfedge of face f that points to its corner v.
inline Halfedge corner_halfedge(const CgalSurfaceMesh& sm, Face f,
                                CgalSurfaceMesh::Vertex_index v) {
    Halfedge h = sm.halfedge(f);
    for (int i = 0; i < 3 && sm.target(h) != v; ++i) h = sm.next(h);
    return h;
}

struct SurfaceMeshMaps {
    CgalSurfaceMesh::Property_map<Halfedge, CgalKernel::Vector_3> normal;
    CgalSurfaceMesh::Property_map<Halfedge, CgalKernel::Point_2> uv;
    CgalSurfaceMesh::Property_map<Face, int> surface;
    bool has_normal = false, has_uv = false, has_surface = false;
};

// Corner normals, corner (u,v) and the source surface of triangle k onto
// face f, whose corners are the vertices `corners`.
inline void set_attributes(CgalSurfaceMesh& sm, const SurfaceMeshMaps& maps,
                           const TriangleMesh& mesh, int k, Face f,
                           const std::array<int, 3>& corners) {
    for (int c = 0; c < 3; ++c) {
        const Halfedge h = corner_halfedge(sm, f, CgalSurfaceMesh::Vertex_index(corners[c]));
        if (maps.has_normal) {
            const Vec3 n = mesh.corner_normals[k][c];
            put(maps.normal, h, CgalKernel::Vector_3(n.x, n.y, n.z));
        }
        if (maps.has_uv)
            put(maps.uv, h,
                CgalKernel::Point_2(mesh.corner_uvs[k][c][0], mesh.corner_uvs[k][c][1]));
    }
    if (maps.has_surface) put(maps.surface, f, mesh.triangle_surface[k]);
}

// The TriangleMesh index of each vertex index (-1: removed): copies of a
// pinched vertex share their original's, other vertices are numbered in order.
inline std::vector<int> vertex_numbers(const CgalSurfaceMesh& sm, TriangleMesh& mesh) {
    using V = CgalSurfaceMesh::Vertex_index;
    std::vector<int> index(sm.num_vertices(), -1);
    const auto [copy_of, copies] = sm.property_map<V, V>(kSurfaceMeshCopyOfMap);
    for (int pass = 0; pass < 2; ++pass)
        for (V v : sm.vertices()) {
            const V original = copies ? get(copy_of, v) : V();
            if (original.is_valid() != (pass == 1)) continue;
            // A copy whose original is gone (removed, or a stale index) stays a vertex.
            if (pass == 1 && std::size_t(original) < index.size() &&
                index[std::size_t(original)] >= 0) {
                index[std::size_t(v)] = index[std::size_t(original)];
                continue;
            }
            index[std::size_t(v)] = mesh.vertex_count();
            const auto& p = sm.point(v);
            mesh.positions.push_back({p.x(), p.y(), p.z()});
        }
    return index;
}

} // namespace surface_mesh_conversion

// The mesh as a Surface_mesh, with the property maps above where the mesh has
// the attributes.
inline CgalSurfaceMesh to_surface_mesh(const TriangleMesh& mesh) {
    using namespace surface_mesh_conversion;
    check_convertible(mesh, "CGAL's Surface_mesh");
    const PinchedVertexCopies split = copy_pinched_vertices(mesh);
    using V = CgalSurfaceMesh::Vertex_index;
    CgalSurfaceMesh sm;
    sm.reserve(mesh.positions.size() + split.copy_of.size(),
               3 * mesh.triangles.size() / 2 + mesh.positions.size(), mesh.triangles.size());
    for (const Vec3& p : mesh.positions) sm.add_vertex(CgalKernel::Point_3(p.x, p.y, p.z));
    if (!split.copy_of.empty()) {
        auto copy_of = sm.add_property_map<V, V>(kSurfaceMeshCopyOfMap).first;
        for (int v : split.copy_of) {
            const Vec3 p = mesh.positions[v];
            put(copy_of, sm.add_vertex(CgalKernel::Point_3(p.x, p.y, p.z)), V(v));
        }
    }
    SurfaceMeshMaps maps;
    maps.has_normal = !mesh.corner_normals.empty();
    maps.has_uv = !mesh.corner_uvs.empty();
    maps.has_surface = !mesh.triangle_surface.empty();
    if (maps.has_normal)
        maps.normal =
            sm.add_property_map<Halfedge, CgalKernel::Vector_3>("h:seamless_normal").first;
    if (maps.has_uv)
        maps.uv = sm.add_property_map<Halfedge, CgalKernel::Point_2>("h:seamless_uv").first;
    if (maps.has_surface) maps.surface = sm.add_property_map<Face, int>("f:seamless_surface").first;
    for (int k = 0; k < mesh.triangle_count(); ++k) {
        const auto& t = split.triangles[k];
        const Face f = sm.add_face(V(t[0]), V(t[1]), V(t[2]));
        if (f == CgalSurfaceMesh::null_face())
            throw InputError("", triangle_field(k),
                             "CGAL's Surface_mesh refuses it: it would make an edge non-manifold "
                             "(a third face, or two faces in the same direction)");
        sm.set_halfedge(f, corner_halfedge(sm, f, V(t[0])));
        set_attributes(sm, maps, mesh, k, f, t);
    }
    return sm;
}

// A Surface_mesh as a TriangleMesh: its vertices and faces in index order
// (removed ones skipped), the property maps above where the mesh has them. A
// face that is not a triangle is an InputError naming it.
inline TriangleMesh from_surface_mesh(const CgalSurfaceMesh& sm) {
    using namespace surface_mesh_conversion;
    TriangleMesh mesh;
    const std::vector<int> index = vertex_numbers(sm, mesh);
    SurfaceMeshMaps maps;
    std::tie(maps.normal, maps.has_normal) =
        sm.property_map<Halfedge, CgalKernel::Vector_3>("h:seamless_normal");
    std::tie(maps.uv, maps.has_uv) =
        sm.property_map<Halfedge, CgalKernel::Point_2>("h:seamless_uv");
    std::tie(maps.surface, maps.has_surface) = sm.property_map<Face, int>("f:seamless_surface");
    for (Face f : sm.faces()) {
        if (sm.degree(f) != 3)
            throw InputError("", "faces[" + std::to_string(std::size_t(f)) + "]",
                             std::to_string(sm.degree(f)) +
                                 " corners; a TriangleMesh holds triangles only "
                                 "(CGAL::Polygon_mesh_processing::triangulate_faces first)");
        Halfedge h = sm.halfedge(f);
        std::array<int, 3> t{};
        std::array<Vec3, 3> n{};
        std::array<std::array<double, 2>, 3> uv{};
        for (int c = 0; c < 3; ++c, h = sm.next(h)) {
            t[c] = index[std::size_t(sm.target(h))];
            if (maps.has_normal) {
                const auto& v = get(maps.normal, h);
                n[c] = {v.x(), v.y(), v.z()};
            }
            if (maps.has_uv) uv[c] = {get(maps.uv, h).x(), get(maps.uv, h).y()};
        }
        mesh.triangles.push_back(t);
        if (maps.has_normal) mesh.corner_normals.push_back(n);
        if (maps.has_uv) mesh.corner_uvs.push_back(uv);
        if (maps.has_surface) mesh.triangle_surface.push_back(get(maps.surface, f));
    }
    return mesh;
}

} // namespace seamless
