// SPDX-License-Identifier: MIT
// What the conversions to other libraries' meshes (openmesh.h, surface_mesh.h)
// require of a TriangleMesh before they add it, checked in one place so both
// name a bad triangle the same way: indices of existing vertices, three
// distinct corners, and attribute arrays that are empty or hold one entry per
// triangle. A mesh built from a user's arrays can break any of these; the
// other library would otherwise crash or drop the triangle silently.
#pragma once

#include <seamless/base/error.h>
#include <seamless/base/triangle_mesh.h>

#include <string>

namespace seamless {

// "triangles[k]": the field an error about triangle k names.
inline std::string triangle_field(int k) {
    return "triangles[" + std::to_string(k) + "]";
}

// Throws InputError naming the first triangle or attribute `target` (the
// library converted to, for the message) cannot take.
inline void check_convertible(const TriangleMesh& mesh, const std::string& target) {
    const int nv = mesh.vertex_count(), nf = mesh.triangle_count();
    for (int k = 0; k < nf; ++k) {
        const auto& t = mesh.triangles[k];
        for (int i : t)
            if (i < 0 || i >= nv)
                throw InputError("", triangle_field(k),
                                 "vertex index " + std::to_string(i) + " out of range (" +
                                     std::to_string(nv) + " vertices)");
        if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0])
            throw InputError("", triangle_field(k),
                             "a corner repeats (" + target + " has no degenerate faces)");
    }
    const auto per_triangle = [&](size_t n, const char* field) {
        if (n != 0 && n != static_cast<size_t>(nf))
            throw InputError(
                "", field, std::to_string(n) + " entries for " + std::to_string(nf) + " triangles");
    };
    per_triangle(mesh.triangle_surface.size(), "triangle_surface");
    per_triangle(mesh.corner_normals.size(), "corner_normals");
    per_triangle(mesh.corner_uvs.size(), "corner_uvs");
}

} // namespace seamless
