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
};

// weld: merge bit-identical positions (all 64 bits of x, y, z, so 0.0 and -0.0
// differ) into the first such vertex; false keeps the mesh's own indices.
WeldedMesh weld_vertices(const TriangleMesh& mesh, bool weld = true);

} // namespace seamless
