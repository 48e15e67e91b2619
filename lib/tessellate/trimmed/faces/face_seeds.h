// SPDX-License-Identifier: MIT
// Seeds of a redone face: a face is redone after a round re-split edges of
// its own (segments its triangles encroached on) or of a neighbour's that it
// shares. Its earlier interior points are inserted again before refinement,
// but those within a new boundary segment's length of a new boundary point
// (a point of the new loops the earlier ones did not have), so that only the
// triangles near the change are refined afresh (triangulate_face's
// `seeds`). Not after a run that failed or ran on beside the sides it
// encroached on (FaceMesh::crowded): its points there would stay.
#pragma once

#include <seamless/tessellate/trimmed/face_surface.h>
#include <seamless/tessellate/trimmed/faces/constrained_triangulation.h>
#include <seamless/tessellate/trimmed/faces/face_domain.h>

namespace seamless {

// Inserts `earlier`'s interior points into cdt and d (the new domain, its
// boundary triangulated in cdt), but those near d's new boundary points.
void insert_seeds(const FaceSurface& s, const FaceDomain& earlier, FaceDomain& d,
                  ConstrainedTriangulation& cdt);

} // namespace seamless
