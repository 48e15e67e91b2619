// SPDX-License-Identifier: MIT
// STEP (AP203, AP214, AP242) and IGES in, through OpenCASCADE's readers: each
// face (or bare surface) becomes one B-spline surface of the model, converted
// exactly where an exact NURBS form exists and approximated otherwise, with
// the approximation error in Model::origins and a warning. A file with
// trimmed faces becomes a B-rep (Model::brep, face k on surface k; its loops
// run with the face on their left in (u, v), whatever BRepFace::reversed
// says) unless ModelLoadOptions::trimmed refuses, skips or takes them whole.
// docs/formats.md documents what is read, fixed and refused.
#pragma once

#include <seamless/model/model.h>

#include <filesystem>
#include <string>

namespace seamless {

// True for ".step", ".stp", ".iges", ".igs" (lower case, with the dot).
bool is_step_iges_extension(const std::string& ext);

// Reads a STEP or IGES file (by extension). Throws InputError naming the file
// when it cannot be read, is not STEP/IGES, holds no surfaces, fails to
// transfer, holds trimmed faces that `options.trimmed` refuses, or (as a
// B-rep) has a face or edge that cannot be represented, named.
Model read_step_iges(const std::filesystem::path& path, const ModelLoadOptions& options = {});

} // namespace seamless
