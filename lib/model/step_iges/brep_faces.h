// SPDX-License-Identifier: MIT
// The faces of a transferred B-rep (brep_reader.cpp): each face's surface
// in its exact NURBS form, its loops of coedges with their pcurves carried
// over to that form's parameters, and the edges and vertices they use. Internal to the STEP/IGES
// module (libseamless_step_iges.so): it exposes OpenCASCADE's types.
#pragma once

#include <seamless/model/model.h>

#include <TopTools_IndexedMapOfShape.hxx>

#include <string>
#include <vector>

namespace seamless::step_iges {

struct FaceContext {
    const TopTools_IndexedMapOfShape& faces; // face k is faces(k + 1)
    const std::vector<std::string>& names;   // of faces, unique
    const std::string& file;
    const ModelLoadOptions& options;
    // The shape's edges and vertices: their indices are the B-rep's, plus one.
    TopTools_IndexedMapOfShape edges, vertices;
};

// Fills m.surfaces, m.origins, and m.brep's vertices, edges, curves,
// pcurves and faces; warns in m.warnings of what was approximated.
void read_faces(const FaceContext& ctx, Model& m);

} // namespace seamless::step_iges
