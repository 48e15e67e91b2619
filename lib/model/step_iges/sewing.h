// SPDX-License-Identifier: MIT
// Faces that a file leaves unconnected (IGES trimmed surfaces, type 144,
// without a B-rep solid around them) sewn into shells: without it each
// face's boundary is its own edge and the mesh cracks at every face border.
// OpenCASCADE's BRepBuilderAPI_Sewing joins edges within the sewing
// tolerance; closed shells become solids oriented outward. Internal to the
// STEP/IGES module: it exposes OpenCASCADE's types.
#pragma once

#include <seamless/model/step_iges/file_transfer.h>

#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Shape.hxx>

#include <string>
#include <vector>

namespace seamless::step_iges {

// The shape the B-rep is read from: the transferred one, or it sewn.
struct SewnShape {
    TopoDS_Shape shape;
    TopTools_IndexedMapOfShape faces; // every face, each once
    std::vector<std::string> names;   // of faces, as the file names the face each came from
    std::string warning;              // what sewing did; empty when it did not run
};

// Sews t's faces when no face of t lies in a shell and there are two or
// more, within the largest of their edges' tolerances (at least 1e-6 of the
// shape's diagonal); else the shape as it is. `names` are t.faces' names.
SewnShape sew_free_faces(const TransferredFile& t, const std::vector<std::string>& names,
                         const std::string& file);

} // namespace seamless::step_iges
