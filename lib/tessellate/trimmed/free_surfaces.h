// SPDX-License-Identifier: MIT
// A model may hold B-rep faces and surfaces that no face uses (a JSON version
// 2 file with both, a scene whose objects mix CAD parts and surface models):
// the faces go through the trimmed pipeline, the free surfaces through the
// Bezier-patch pipeline of section 6, and the two meshes are joined. They
// share no edge, so nothing is matched across them.
#pragma once

#include <seamless/model/model.h>
#include <seamless/tessellate/tessellation_result.h>

#include <vector>

namespace seamless {

// The surfaces of m that no B-rep face uses, in index order.
std::vector<int> free_surfaces(const Model& m);

// The model of those surfaces alone (no B-rep).
Model free_surface_model(const Model& m, const std::vector<int>& surfaces);

// Appends `part` (a tessellation of free_surface_model(m, surfaces)) to `into`:
// vertices, triangles, per-triangle attributes (triangle_surface mapped back
// through `surfaces`), patch trees and subpatches with their indices moved
// past those already there; the counts of the stats added.
void append_tessellation(Tessellation& into, const Tessellation& part,
                         const std::vector<int>& surfaces);

} // namespace seamless
