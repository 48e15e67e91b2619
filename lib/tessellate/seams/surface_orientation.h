// SPDX-License-Identifier: MIT
// Consistent orientation of the surfaces of a tessellation. A CAD file's
// surfaces need not agree on which side their normal dP/du x dP/dv points to
// (IGES type 128 surfaces carry no face orientation; tire.iges mixes both), so
// two surfaces sharing a seam may run along it in the same direction. Each
// surface is flipped as a whole where that makes every shared edge run in
// opposite directions on its two sides, then every closed component is turned
// to face outward (positive signed volume).
#pragma once

#include <seamless/base/triangle_mesh.h>

namespace seamless {

struct OrientationResult {
    int flipped_surfaces = 0;
    // Surface pairs whose shared edges disagree among themselves (the union is
    // not orientable surface by surface); left as they are.
    int conflicts = 0;
};

// Flips whole surfaces (triangle_surface) of `mesh`: triangle windings,
// corner normals and corner uvs. Needs triangle_surface; deterministic, the
// same for any number of worker threads (parallel.h: 0 every core, 1 sequential).
OrientationResult orient_surfaces(TriangleMesh& mesh, int threads = 1);

} // namespace seamless
