// SPDX-License-Identifier: MIT
// Measures of closed shells for the watertightness check (docs/check.md, step
// 11): Euler characteristic, genus, and through CGAL's Polygon_mesh_processing
// the enclosed volume and whether the orientation is outward.
#pragma once

#include <seamless/mesh/check/edge_topology.h>

namespace seamless {

// Fills euler, genus, volume and outward of every closed shell of `shells`
// (genus only when the shell is manifold and consistently oriented; volume and
// outward only when it is also a valid closed CGAL Surface_mesh).
void measure_closed_shells(const WeldedMesh& mesh, Shells& shells);

} // namespace seamless
