// SPDX-License-Identifier: MIT
// Subcommands of the seamless program. Each add_* registers its options and a
// callback; the callback throws seamless::InputError for bad input (exit 2) and
// returns the process exit status otherwise.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>

namespace seamless::cli {

// The callback a subcommand leaves for main() to run after parsing.
using Action = std::function<int()>;

void add_info(CLI::App& app, Action& action);
void add_tessellate(CLI::App& app, Action& action);
void add_convert(CLI::App& app, Action& action);
void add_check(CLI::App& app, Action& action);
void add_render(CLI::App& app, Action& action);
void add_sweep(CLI::App& app, Action& action);
void add_batch(CLI::App& app, Action& action);

} // namespace seamless::cli
