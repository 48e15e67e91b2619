// SPDX-License-Identifier: MIT
// Validators for the options that take a length, a tolerance or a factor:
// a finite number, with a short message naming the bound. CLI11's
// PositiveNumber accepts NaN and prints its range up to DBL_MAX in full
// ("not in range 0.000000 to 1797693...000.000000").
#pragma once

#include <CLI/CLI.hpp>

#include <cmath>
#include <string>

namespace seamless::cli {

enum class Bound { positive, non_negative, any };

inline CLI::Validator finite_number(Bound bound) {
    const char* what = bound == Bound::positive       ? "a finite number > 0"
                       : bound == Bound::non_negative ? "a finite number >= 0"
                                                      : "a finite number";
    return CLI::Validator(
        [bound, what](std::string& s) -> std::string {
            double v = 0;
            const bool ok =
                CLI::detail::lexical_cast(s, v) && std::isfinite(v) &&
                (bound == Bound::any || v > 0 || (bound == Bound::non_negative && v == 0));
            return ok ? std::string() : std::string("expected ") + what + ", got '" + s + "'";
        },
        bound == Bound::positive       ? "NUMBER > 0"
        : bound == Bound::non_negative ? "NUMBER >= 0"
                                       : "NUMBER");
}

} // namespace seamless::cli
