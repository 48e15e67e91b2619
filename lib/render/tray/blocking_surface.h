// SPDX-License-Identifier: MIT
// SHADE step 2 (paper section 7): a light certainly blocked for a cluster of
// points by a surface of triangles, where no single triangle covers the
// light's pyramid (Proposition 11 and Theorem 6 iii prove coverage by one).
#pragma once

#include <seamless/base/vec.h>
#include <seamless/interval/interval_matrix.h>

#include <array>
#include <vector>

namespace seamless {

// Neighbours across the edges of a triangle mesh: out[3 t + e] is the triangle
// traversing edge e of triangle t (its vertices e and e + 1 mod 3) in the
// opposite direction, or -1 where there is none, or where the edge is not a
// manifold, consistently oriented one (more than two triangles on it, or two
// traversing it in the same direction).
std::vector<int> triangle_neighbours(const std::vector<std::array<int, 3>>& triangles);

// A light certainly blocked by a surface of triangles rather than by one (SHADE
// step 2; Proposition 11 and Theorem 6 iii prove coverage by one triangle,
// which fails wherever the light's pyramid crosses a triangle's edge). The
// surface S grows from `seed` across every edge of the mesh (neighbours:
// triangle_neighbours) that may meet the pyramid from `apex` over the box
// `ends`; true when
//  a) every triangle of S faces the apex with the seed's strict orientation
//     and lies strictly between the apex and a plane across the pyramid,
//     beyond which the box lies, at ray parameters q < q_max; no triangle t
//     of S has group[t] == skip (a surface that may not block: the lit patch);
//  b) so every edge on the border of S (no consistently oriented neighbour in
//     S across it) certainly misses the pyramid;
//  c) the ray to the box's midpoint certainly meets the seed (Theorem 6 iii).
// Then every ray meets S before q_max: seen from the apex, S maps to the
// sphere of directions preserving orientation triangle by triangle, and by
// the consistent orientation across inner edges the map is open inside S, so
// the border of S's image lies in the image of S's border edges. The
// connected set of the pyramid's directions misses those by b) and meets the
// image by c), so it lies inside the image. max_size bounds S (false beyond).
struct SurfaceScratch {
    std::vector<unsigned> stamp; // per triangle: == epoch when in S
    unsigned epoch = 0;
    std::vector<int> stack;
};
// The pyramid from a light at `apex` over the box of end points `ends`, its
// rays' parameters below q_max.
struct LightPyramid {
    Vec3 apex;
    const IVec<3>& ends;
    double q_max;
};
// The mesh S grows in: its triangles' corners, neighbours and groups.
struct BlockerMesh {
    const std::vector<Vec3>& positions;
    const std::vector<std::array<int, 3>>& triangles;
    const std::vector<int>& neighbours;
    const std::vector<int>& group;
};
bool pyramid_blocked_by_surface(const LightPyramid& pyramid, int seed, const BlockerMesh& mesh,
                                int skip, int max_size, SurfaceScratch& scratch);

} // namespace seamless
