// SPDX-License-Identifier: MIT
#include <seamless/model/step_iges/messages.h>

#include <algorithm>
#include <sstream>

namespace seamless::step_iges {

std::string fmt(double x, int digits) {
    std::ostringstream os;
    os.precision(digits);
    os << x;
    return os.str();
}

std::string list_names(const std::vector<std::string>& names) {
    std::string s;
    const size_t shown = std::min<size_t>(names.size(), 20);
    for (size_t k = 0; k < shown; ++k) s += (k ? ", " : "") + names[k];
    if (names.size() > shown) s += ", ... " + std::to_string(names.size() - shown) + " more";
    return s;
}

std::string count_of(size_t n, const std::string& noun) {
    return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

} // namespace seamless::step_iges
