// SPDX-License-Identifier: MIT
// seamless tessellate: placeholder until lib/tessellate lands.
#include "commands.h"

namespace seamless::cli {
void add_tessellate(CLI::App&, Action&) {}
} // namespace seamless::cli
