// SPDX-License-Identifier: MIT
// Triangle defects for the watertightness check (docs/check.md, steps 7, 8 and
// 10), the only part decided by CGAL's exact predicates: degenerate (zero-area)
// triangles, duplicated triangles (hashed by their sorted vertex triple), and
// intersecting triangle pairs, within one shell (self-intersections), between
// shells of one body (overlaps) or between bodies (contacts: solids or parts
// judged apart, weld.h).
#pragma once

#include <seamless/mesh/check/border_defects.h>
#include <seamless/mesh/check/edge_topology.h>

#include <vector>

namespace seamless {

struct TriangleDefect {
    int triangle = -1;
    Vec3 location; // centroid
};

// Zero area, exactly: a repeated vertex or three collinear points.
std::vector<TriangleDefect> degenerate_triangles(const WeldedMesh& mesh);

// Pairs (t0, t1): t1 repeats the vertex set of t0, the first triangle with it
// (either orientation). One pair per repeat, so k copies give k - 1 pairs.
std::vector<TrianglePair> duplicated_triangles(const WeldedMesh& mesh);

struct Intersections {
    std::vector<TrianglePair> self_intersections; // within one shell, sorted by (t0, t1)
    std::vector<TrianglePair> overlaps;           // between shells, sorted by (t0, t1)
    std::vector<TrianglePair> contacts;           // between bodies, sorted by (t0, t1)
};

// Pairs of non-degenerate triangles whose boxes overlap and that intersect by
// exact predicates, beyond what they share (adjacency rules of CGAL PMP
// self_intersections). A triangle is first cut at the T-junction vertices on its
// edges. Of duplicated triangles only the first takes part (its copies are
// reported as duplicates), so k copies cost O(k), not O(k^2) pairs; likewise
// without welding of triangles with bit-identical corner positions.
Intersections find_intersections(const WeldedMesh& mesh, const std::vector<int>& triangle_shell,
                                 const std::vector<TriangleDefect>& degenerate,
                                 const std::vector<TrianglePair>& duplicated,
                                 const std::vector<TJunction>& t_junctions);

} // namespace seamless
