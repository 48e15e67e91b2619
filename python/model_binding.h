// SPDX-License-Identifier: MIT
// Reading a model for the module's functions that take a model or its path.
#pragma once

#include <seamless/model/model.h>

#include <memory>
#include <string>

namespace seamless::python {

// ModelLoadOptions of the `trimmed` argument ("brep", "refuse", "skip",
// "whole_surface"); InputError for anything else.
ModelLoadOptions load_options(const std::string& trimmed);

// load_model with the GIL released (called with it held).
std::shared_ptr<Model> load(const std::string& path, const std::string& trimmed);

} // namespace seamless::python
