// SPDX-License-Identifier: MIT
// The largest and smallest of three doubles by two comparisons: the values
// of std::max({a, b, c}) and std::min({a, b, c}) (the first of equal ones,
// NaN kept out alike: each step is `x < y`), without the initializer list,
// which the compiler walked as a loop in the bounds' refined-triangle loops
// (fan_bound.cpp, certified_fan_bound.cpp).
#pragma once

#include <algorithm>

namespace seamless {

inline double max3(double a, double b, double c) {
    return std::max(std::max(a, b), c);
}
inline double min3(double a, double b, double c) {
    return std::min(std::min(a, b), c);
}

} // namespace seamless
