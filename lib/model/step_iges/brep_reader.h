// SPDX-License-Identifier: MIT
// A transferred STEP/IGES file as a boundary representation (model/brep.h):
// every face on its own B-spline surface, with loops of coedges whose
// pcurves share their edge's parameter. Internal to the STEP/IGES module
// (libseamless_step_iges.so): it exposes OpenCASCADE's types.
#pragma once

#include <seamless/model/model.h>
#include <seamless/model/step_iges/file_transfer.h>

#include <string>
#include <vector>

namespace seamless::step_iges {

// The model of t as a B-rep: Model::surfaces (surface k for face k of
// t.faces, named names[k]), Model::origins, Model::brep and the warnings
// for what was healed, approximated or found beyond an edge's tolerance.
// Throws InputError naming the file and the face or edge that cannot be
// represented.
Model read_brep(const TransferredFile& t, const std::vector<std::string>& names,
                const std::string& file, const ModelLoadOptions& options);

} // namespace seamless::step_iges
