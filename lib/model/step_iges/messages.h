// SPDX-License-Identifier: MIT
// Pieces of the STEP/IGES reader's one-line messages.
#pragma once

#include <string>
#include <vector>

namespace seamless::step_iges {

// x with `digits` significant digits.
std::string fmt(double x, int digits = 3);

// "a, b, c", the first 20 and then "... N more".
std::string list_names(const std::vector<std::string>& names);

// "3 faces", "1 face".
std::string count_of(size_t n, const std::string& noun);

} // namespace seamless::step_iges
