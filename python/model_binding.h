// SPDX-License-Identifier: MIT
// Reading a model for the module's functions that take a model or its path.
#pragma once

#include <seamless/base/triangle_mesh.h>
#include <seamless/model/model.h>

#include <memory>
#include <string>
#include <vector>

namespace seamless::python {

// ModelLoadOptions of the `trimmed` argument ("brep", "refuse", "skip",
// "whole_surface"); InputError for anything else.
ModelLoadOptions load_options(const std::string& trimmed);

// load_model with the GIL released (called with it held).
std::shared_ptr<Model> load(const std::string& path, const std::string& trimmed);

// Each triangle's B-rep face (face_id.cpp): empty without a B-rep or
// without per-triangle surfaces; -1 where the surface does not name one face.
std::vector<int> brep_face_ids(const Model& model, const TriangleMesh& mesh);

} // namespace seamless::python
