// SPDX-License-Identifier: MIT
// seamless check: placeholder until lib/mesh/check lands.
#include "commands.h"

namespace seamless::cli {
void add_check(CLI::App&, Action&) {}
} // namespace seamless::cli
