// SPDX-License-Identifier: MIT
// Loops that run along each other within tolerance in a face's (u,v)
// domain: where a face's boundary touches itself along a length (an end cap
// whose edge runs along the face's side edge, the face between them of no
// width), the two pcurves, each within its edge's tolerance, wobble across
// each other, and halving their segments never parts them. The crossing
// points are moved, on this face's (u,v) domain only, a small fraction of the
// tolerance onto the face's side of the segment they cross; their 3D points,
// which the neighbouring faces share, stay.
#pragma once

#include <seamless/model/model.h>
#include <seamless/tessellate/trimmed/faces/face_domain.h>

namespace seamless {

// Moves the boundary points that make the loops cross, where they lie
// within their edges' tolerance of the segment they cross; true when any
// moved. Of two edges, the one whose (u,v) images map farther from its 3D
// points moves. Crossings farther apart are left to re-splitting.
bool separate_touching_loops(const BRep& brep, const FaceSurface& surface, FaceDomain& d);

} // namespace seamless
