// SPDX-License-Identifier: MIT
// Builders the certified-bound tests share: surfaces as CAD files write them,
// and a mesh triangle's corners and certified bound.
#pragma once

#include <seamless/base/triangle_mesh.h>
#include <seamless/model/model.h>
#include <seamless/tessellate/trimmed/bounds/triangle_bound.h>
#include <seamless/tessellate/trimmed/face_surface.h>

#include <array>
#include <cmath>

namespace seamless::test {

// The segment from radius r0 at height z0 to radius r1 at height z1 revolved
// about the z axis, as OpenCASCADE writes a cylinder or cone: the circle a
// rational quadratic in u over [0, 1] with double knots (a C0 basis, a C1
// curve), the segment a line in v over [0, 1].
inline BSplineSurface revolved_segment(double r0, double z0, double r1, double z1) {
    BSplineSurface s;
    s.degree_u = 2, s.degree_v = 1;
    s.size_u = 9, s.size_v = 2;
    s.knots_u = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
    s.knots_v = {0, 0, 1, 1};
    const double w = std::sqrt(0.5);
    const double cx[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1}, cy[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
    const double r[2] = {r0, r1}, z[2] = {z0, z1};
    for (int i = 0; i < 9; ++i)
        for (int j = 0; j < 2; ++j) {
            s.points.push_back({r[j] * cx[i], r[j] * cy[i], z[j]});
            s.weights.push_back(i % 2 ? w : 1.0);
        }
    return s;
}

// Triangle f of a B-rep model's mesh: its corners' (u,v) and positions, and
// the certified bound of its distance to its face's surface.
struct MeshTriangleBound {
    std::array<UV, 3> uv;
    std::array<Vec3, 3> Q;
    double bound = 0;
};

inline MeshTriangleBound mesh_triangle_bound(const Model& model, const TriangleMesh& m, int f) {
    const BSplineSurface& s = model.surfaces[m.triangle_surface[f]];
    const FaceSurface face(s);
    const TriangleBound bound(s, face.closed_u(), face.closed_v());
    MeshTriangleBound out;
    for (int k = 0; k < 3; ++k)
        out.uv[k] = {m.corner_uvs[f][k][0], m.corner_uvs[f][k][1]},
        out.Q[k] = m.positions[m.triangles[f][k]];
    out.bound = bound(out.uv, out.Q);
    return out;
}

} // namespace seamless::test
