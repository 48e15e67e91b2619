// SPDX-License-Identifier: MIT
// Welding for the watertightness check (docs/check.md, step 1): vertices with
// bit-identical positions become one, so a seam whose two sides repeat the same
// points is one edge. The other check steps work on the welded, indexed mesh.
#pragma once

#include <seamless/base/triangle_mesh.h>

#include <array>
#include <vector>

namespace seamless {

// The mesh the check judges: positions and triangles after welding.
struct WeldedMesh {
    std::vector<Vec3> positions;               // #V', model units
    std::vector<std::array<int, 3>> triangles; // #F indices into positions
    std::vector<char> referenced;              // #V' 1 when some triangle uses the vertex
    int welded_vertices = 0;       // input vertices merged into an earlier identical one
    int unreferenced_vertices = 0; // vertices no triangle uses
    // Bodies judged apart (solids or parts, check.h): #F body id of each
    // triangle, empty when the mesh is judged whole. No vertex is shared by
    // two bodies: body_copies vertices were copied for a further body.
    std::vector<int> triangle_body;
    int body_copies = 0;

    // Whether triangles s and t belong to one body.
    bool same_body(int s, int t) const {
        return triangle_body.empty() || triangle_body[s] == triangle_body[t];
    }
};

// weld: merge bit-identical positions (all 64 bits of x, y, z, so 0.0 and -0.0
// differ) into the first such vertex; false keeps the mesh's own indices.
// triangle_body (#F, or empty): then a vertex that triangles of several
// bodies use is kept for the body of its first triangle and copied, after
// all others, once for each further body, so that bodies touching at
// vertices and edges are judged apart.
WeldedMesh weld_vertices(const TriangleMesh& mesh, bool weld = true,
                         std::vector<int> triangle_body = {});

} // namespace seamless
