// SPDX-License-Identifier: MIT
// Mesh.face_id: each triangle's B-rep face, where the model says it. The
// library's meshes carry the source surface of each triangle
// (TriangleMesh::triangle_surface); a STEP/IGES B-rep has one surface per
// face, so there the surface names the face. Where several faces share a
// surface (a JSON B-rep may) or a surface has no face, the face is not known
// from the surface and the id is -1. Per-triangle face ids in the library
// itself are issue 29's; this reads only what the mesh already holds.
#include "model_binding.h"

#include <algorithm>

namespace seamless::python {

std::vector<int> brep_face_ids(const Model& model, const TriangleMesh& mesh) {
    if (model.brep.empty() || mesh.triangle_surface.empty()) return {};
    // face_on[s]: the one face on surface s, -1 for none, -2 for several.
    std::vector<int> face_on(model.surfaces.size(), -1);
    for (int f = 0; f < static_cast<int>(model.brep.faces.size()); ++f) {
        const int s = model.brep.faces[f].surface;
        if (s >= 0 && s < static_cast<int>(face_on.size())) face_on[s] = face_on[s] == -1 ? f : -2;
    }
    std::vector<int> ids(mesh.triangle_surface.size(), -1);
    for (size_t t = 0; t < ids.size(); ++t) {
        const int s = mesh.triangle_surface[t];
        if (s >= 0 && s < static_cast<int>(face_on.size())) ids[t] = std::max(face_on[s], -1);
    }
    return ids;
}

} // namespace seamless::python
