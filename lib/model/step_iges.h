// SPDX-License-Identifier: MIT
// STEP (AP203, AP214, AP242) and IGES in, through OpenCASCADE's readers: each
// face (or bare surface) becomes one B-spline surface of the model, converted
// exactly where an exact NURBS form exists and approximated otherwise, with
// the approximation error in Model::origins and a warning. Trimmed faces are
// refused, skipped or taken whole as ModelLoadOptions::trimmed says.
// docs/formats.md documents what is read and refused.
#pragma once

#include <seamless/model/model.h>

#include <filesystem>
#include <string>

namespace seamless {

// True for ".step", ".stp", ".iges", ".igs" (lower case, with the dot).
bool is_step_iges_extension(const std::string& ext);

// Reads a STEP or IGES file (by extension). Throws InputError naming the file
// when it cannot be read, is not STEP/IGES, holds no surfaces, fails to
// transfer, or holds trimmed faces that `options.trimmed` refuses.
Model read_step_iges(const std::filesystem::path& path, const ModelLoadOptions& options = {});

} // namespace seamless
