// SPDX-License-Identifier: MIT
// Checks of the module's numeric keyword arguments, as the CLI checks its
// options: an InputError naming the keyword.
#pragma once

#include <seamless/base/error.h>

#include <cmath>
#include <sstream>
#include <string>

namespace seamless::python {

inline std::string number_text(double x) {
    std::ostringstream os;
    os << x;
    return os.str();
}

inline double positive(double x, const char* keyword) {
    if (!std::isfinite(x) || x <= 0)
        throw InputError("", keyword, "expected a positive finite number, got " + number_text(x));
    return x;
}

inline double non_negative(double x, const char* keyword) {
    if (!std::isfinite(x) || x < 0)
        throw InputError("", keyword,
                         "expected a non-negative finite number, got " + number_text(x));
    return x;
}

inline double in_range(double x, double lo, double hi, const char* keyword) {
    if (!(x >= lo && x <= hi))
        throw InputError("", keyword,
                         "expected a number in " + number_text(lo) + ".." + number_text(hi) +
                             ", got " + number_text(x));
    return x;
}

} // namespace seamless::python
