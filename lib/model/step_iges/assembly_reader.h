// SPDX-License-Identifier: MIT
// A transferred file with an assembly (cad_structure.h) as a model that keeps
// it: each distinct part read once by read_brep, in its own coordinates,
// the parts' B-reps one after another, and the tree, names and colours in
// Model::assembly. Internal to the STEP/IGES module: it exposes
// OpenCASCADE's types.
#pragma once

#include <seamless/model/model.h>
#include <seamless/model/step_iges/cad_structure.h>

#include <string>

namespace seamless::step_iges {

// Throws InputError as read_brep does, naming the file and the face or edge.
Model read_assembly(const TransferredFile& t, CadStructure structure, const std::string& file,
                    const ModelLoadOptions& options);

} // namespace seamless::step_iges
