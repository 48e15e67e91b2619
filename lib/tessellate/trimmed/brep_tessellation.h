// SPDX-License-Identifier: MIT
// Tessellation of a B-rep's trimmed faces (issue 28, section 2), the room
// beside the Bezier-patch pipeline: topology first (every edge discretised
// once, edge_discretisation.h), then every face triangulated in its (u,v)
// domain with its loops as constraints (face_triangulation.h); faces whose
// loops do not triangulate get their edges re-split on both sides. The mesh
// of a closed solid comes out closed because faces share their edges'
// points by index. Faces run in parallel into per-face slots concatenated in
// face order: the output is the same for any thread count. No patch trees or
// subpatches; the deviation is measured (sampled), not certified.
#pragma once

#include <seamless/model/model.h>
#include <seamless/tessellate/tessellation_options.h>
#include <seamless/tessellate/tessellation_result.h>

namespace seamless {

// The deviation D used: TessellationOptions::tolerance when > 0, else eps1
// when given, else 1e-3 of the diagonal of the box of the B-rep's vertices and
// edge curves' control points (what OpenCASCADE's users expect).
double brep_deviation(const Model& model, const TessellationOptions& options);

// Multiplies every length of the model by s: control points of surfaces and
// curves, vertices, tolerances (not the pcurves' (u,v)).
void scale_lengths(Model& m, double s);

// Throws InputError naming a face that cannot be triangulated (unless
// options.allow_holes) and TriangleBudgetError past options.max_triangles.
Tessellation tessellate_brep(const Model& model, const TessellationOptions& options);

} // namespace seamless
