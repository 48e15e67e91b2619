// SPDX-License-Identifier: MIT
// TriangleMesh <-> OpenMesh's triangle mesh with double-precision points, both
// ways, nothing rounded to float (docs/cpp.md).
//
// Opt-in and header-only: this is the one header of lib/ that includes
// OpenMesh, against the rule that third-party libraries stay in .cpp files,
// because its whole point is OpenMesh's type. libseamless neither includes nor
// links OpenMesh; a program that includes this header links OpenMeshCore
// itself. No other seamless header includes it (tests/layering checks).
//
// What maps: positions bit for bit; triangles in order, each with its first
// corner first (the face's halfedge is set to the one pointing to it); corner
// normals as halfedge normals and corner (u,v) as halfedge texture
// coordinates (per corner, as a seam vertex needs); triangle_surface as the
// face property "seamless:surface", surface_names as the mesh property
// "seamless:surface_names". A vertex where triangles meet in several fans
// (pinched_vertices.h) becomes one OpenMesh vertex per fan, the copies marked
// by the vertex property "seamless:copy_of", which from_openmesh merges
// again (OpenMesh's garbage_collection does not renumber that property:
// convert back before collecting). What does not map: an edge of three
// faces, or of two faces in the same direction; OpenMesh refuses the face and
// to_openmesh throws an InputError naming the triangle, never a silent drop.
#pragma once

#include <seamless/mesh/convertible_mesh.h>
#include <seamless/mesh/pinched_vertices.h>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <string>
#include <type_traits>
#include <vector>

namespace seamless {

// OpenMesh's default traits hold floats; these hold the library's doubles.
struct OpenMeshDoubleTraits : OpenMesh::DefaultTraits {
    typedef OpenMesh::Vec3d Point;
    typedef OpenMesh::Vec3d Normal;
    typedef OpenMesh::Vec2d TexCoord2D;
};
using OpenMeshTriMesh = OpenMesh::TriMesh_ArrayKernelT<OpenMeshDoubleTraits>;

inline const char* const kOpenMeshSurfaceProperty = "seamless:surface";
inline const char* const kOpenMeshNamesProperty = "seamless:surface_names";
// A vertex property (VertexHandle): the vertex a copy of a pinched vertex
// stands for (pinched_vertices.h); invalid for every other vertex.
inline const char* const kOpenMeshCopyOfProperty = "seamless:copy_of";

namespace openmesh_conversion {

// The halfedge of face f that points to its corner v.
template <class OMesh>
typename OMesh::HalfedgeHandle corner_halfedge(const OMesh& om, typename OMesh::FaceHandle f,
                                               typename OMesh::VertexHandle v) {
    auto h = om.halfedge_handle(f);
    for (int i = 0; i < 3 && om.to_vertex_handle(h) != v; ++i) h = om.next_halfedge_handle(h);
    return h;
}

// Corner normals, corner (u,v) and the source surface of triangle k onto
// face f, whose corners are the vertices `corners`.
template <class OMesh>
void set_corner_attributes(OMesh& om, const TriangleMesh& mesh, int k, typename OMesh::FaceHandle f,
                           const std::array<int, 3>& corners, OpenMesh::FPropHandleT<int> surface) {
    for (int c = 0; c < 3; ++c) {
        const auto h = corner_halfedge(om, f, om.vertex_handle(corners[c]));
        if (!mesh.corner_normals.empty()) {
            const Vec3 n = mesh.corner_normals[k][c];
            om.set_normal(h, typename OMesh::Normal(n.x, n.y, n.z));
        }
        if (!mesh.corner_uvs.empty()) {
            const auto& uv = mesh.corner_uvs[k][c];
            om.set_texcoord2D(h, typename OMesh::TexCoord2D(uv[0], uv[1]));
        }
    }
    if (!mesh.triangle_surface.empty()) om.property(surface, f) = mesh.triangle_surface[k];
}

// The TriangleMesh index of each OpenMesh vertex (-1: deleted): copies of a
// pinched vertex share their original's, other vertices are numbered in order.
template <class OMesh> std::vector<int> vertex_numbers(const OMesh& om, TriangleMesh& mesh) {
    std::vector<int> index(om.n_vertices(), -1);
    OpenMesh::VPropHandleT<typename OMesh::VertexHandle> copy_of;
    const bool copies = om.get_property_handle(copy_of, kOpenMeshCopyOfProperty);
    for (int pass = 0; pass < 2; ++pass)
        for (auto v : om.vertices()) {
            const auto original = copies ? om.property(copy_of, v) : typename OMesh::VertexHandle();
            if (original.is_valid() != (pass == 1)) continue;
            // A copy whose original is gone (deleted, or a stale handle) stays a vertex.
            if (pass == 1 && original.idx() < static_cast<int>(index.size()) &&
                index[original.idx()] >= 0) {
                index[v.idx()] = index[original.idx()];
                continue;
            }
            index[v.idx()] = mesh.vertex_count();
            const auto& p = om.point(v);
            mesh.positions.push_back({double(p[0]), double(p[1]), double(p[2])});
        }
    return index;
}

} // namespace openmesh_conversion

// The mesh in OpenMesh. OMesh: OpenMeshTriMesh or a mesh of the user's whose
// points, normals and texture coordinates are doubles too.
template <class OMesh = OpenMeshTriMesh> OMesh to_openmesh(const TriangleMesh& mesh) {
    static_assert(std::is_same_v<typename OMesh::Point::value_type, double> &&
                      std::is_same_v<typename OMesh::Normal::value_type, double> &&
                      std::is_same_v<typename OMesh::TexCoord2D::value_type, double>,
                  "to_openmesh keeps doubles: use traits with Vec3d points and normals and "
                  "Vec2d texture coordinates (OpenMeshDoubleTraits)");
    check_convertible(mesh, "OpenMesh");
    const PinchedVertexCopies split = copy_pinched_vertices(mesh);
    OMesh om;
    om.reserve(mesh.positions.size() + split.copy_of.size(),
               3 * mesh.triangles.size() / 2 + mesh.positions.size(), mesh.triangles.size());
    for (const Vec3& p : mesh.positions) om.add_vertex(typename OMesh::Point(p.x, p.y, p.z));
    if (!split.copy_of.empty()) {
        OpenMesh::VPropHandleT<typename OMesh::VertexHandle> copy_of;
        om.add_property(copy_of, kOpenMeshCopyOfProperty);
        for (int v : split.copy_of) {
            const Vec3 p = mesh.positions[v];
            om.property(copy_of, om.add_vertex(typename OMesh::Point(p.x, p.y, p.z))) =
                om.vertex_handle(v);
        }
    }
    if (!mesh.corner_normals.empty()) om.request_halfedge_normals();
    if (!mesh.corner_uvs.empty()) om.request_halfedge_texcoords2D();
    OpenMesh::FPropHandleT<int> surface;
    if (!mesh.triangle_surface.empty()) om.add_property(surface, kOpenMeshSurfaceProperty);
    for (int k = 0; k < mesh.triangle_count(); ++k) {
        const auto& t = split.triangles[k];
        const auto f =
            om.add_face(om.vertex_handle(t[0]), om.vertex_handle(t[1]), om.vertex_handle(t[2]));
        if (!f.is_valid())
            throw InputError("", triangle_field(k),
                             "OpenMesh refuses it: it would make an edge complex (non-manifold: a "
                             "third face, or two faces in the same direction)");
        om.set_halfedge_handle(f,
                               openmesh_conversion::corner_halfedge(om, f, om.vertex_handle(t[0])));
        openmesh_conversion::set_corner_attributes(om, mesh, k, f, t, surface);
    }
    if (!mesh.surface_names.empty()) {
        OpenMesh::MPropHandleT<std::vector<std::string>> names;
        om.add_property(names, kOpenMeshNamesProperty);
        om.property(names) = mesh.surface_names;
    }
    return om;
}

// An OpenMesh mesh (any traits: float coordinates widen exactly) as a
// TriangleMesh: its vertices and faces in OpenMesh's order (deleted ones
// skipped), the attributes above where the mesh has them. A face of a
// polygon mesh that is not a triangle is an InputError naming it.
template <class OMesh> TriangleMesh from_openmesh(const OMesh& om) {
    TriangleMesh mesh;
    const std::vector<int> index = openmesh_conversion::vertex_numbers(om, mesh);
    OpenMesh::FPropHandleT<int> surface;
    const bool surfaces = om.get_property_handle(surface, kOpenMeshSurfaceProperty);
    for (auto f : om.faces()) {
        if (om.valence(f) != 3)
            throw InputError("", "faces[" + std::to_string(f.idx()) + "]",
                             std::to_string(om.valence(f)) +
                                 " corners; a TriangleMesh holds triangles only");
        auto h = om.halfedge_handle(f);
        std::array<int, 3> t{};
        std::array<Vec3, 3> n{};
        std::array<std::array<double, 2>, 3> uv{};
        for (int c = 0; c < 3; ++c, h = om.next_halfedge_handle(h)) {
            t[c] = index[om.to_vertex_handle(h).idx()];
            if (om.has_halfedge_normals())
                for (int i = 0; i < 3; ++i) n[c][i] = double(om.normal(h)[i]);
            if (om.has_halfedge_texcoords2D())
                uv[c] = {double(om.texcoord2D(h)[0]), double(om.texcoord2D(h)[1])};
        }
        mesh.triangles.push_back(t);
        if (om.has_halfedge_normals()) mesh.corner_normals.push_back(n);
        if (om.has_halfedge_texcoords2D()) mesh.corner_uvs.push_back(uv);
        if (surfaces) mesh.triangle_surface.push_back(om.property(surface, f));
    }
    OpenMesh::MPropHandleT<std::vector<std::string>> names;
    if (om.get_property_handle(names, kOpenMeshNamesProperty))
        mesh.surface_names = om.property(names);
    return mesh;
}

} // namespace seamless
