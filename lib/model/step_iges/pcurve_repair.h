// SPDX-License-Identifier: MIT
// Pcurves that a file got wrong, recomputed: a coedge's curve on its face's
// surface that strays from its edge's 3D curve far beyond the edge's
// tolerance (a pcurve on the wrong side of a closed surface, one that
// stands still while its 3D curve moves) makes a face's loops cross in
// (u,v) where they do not in space. Such pcurves are replaced by the 3D
// curve projected onto the surface (OpenCASCADE's ShapeFix_Edge) when the
// projection follows the 3D curve better. Internal to the STEP/IGES module:
// it exposes OpenCASCADE's types.
#pragma once

#include <TopTools_IndexedMapOfShape.hxx>

#include <string>
#include <vector>

namespace seamless::step_iges {

// Recomputes the straying pcurves of `faces` in place (the shape's edges
// are shared, so every face using an edge sees it). Returns the warning
// naming what was recomputed, empty when nothing was. `names` are the
// faces' names, `file` the file's for the message.
std::string repair_pcurves(const TopTools_IndexedMapOfShape& faces,
                           const std::vector<std::string>& names, const std::string& file);

} // namespace seamless::step_iges
