// SPDX-License-Identifier: MIT
// The length unit a STEP or IGES file gives its coordinates in, read from
// the file's text: seamless keeps a file's numbers as they are (the reader
// does not convert to millimetres, docs/formats.md), so the unit is what
// turns them into metres for formats that have one (glTF).
#pragma once

#include <filesystem>
#include <string>

namespace seamless {

// Metres per unit of the coordinates load_model reads from `path`: STEP's
// length unit of the first unit context in the file (the one the reader keeps:
// SI_UNIT with its prefix, or a CONVERSION_BASED_UNIT such as INCH through
// its measure), IGES's unit flag and name (global parameters 14 and 15). 0
// when the file is neither or names no length unit it can read (a JSON
// model records none).
double file_length_unit(const std::filesystem::path& path);

// The same from a file's text; `iges` selects the format.
double step_length_unit(const std::string& text);
double iges_length_unit(const std::string& text);

} // namespace seamless
