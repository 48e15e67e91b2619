// SPDX-License-Identifier: MIT
// The options of every subcommand that reads a model (STEP/IGES trimmed
// faces), and printing the reader's warnings.
#pragma once

#include <seamless/model/model.h>

#include <CLI/CLI.hpp>

namespace seamless::cli {

// Adds --skip-trimmed and --untrimmed to `cmd`, filling `options.trimmed`.
void add_model_options(CLI::App* cmd, ModelLoadOptions& options);

// One "warning: ..." line on stderr per Model::warnings entry.
void print_warnings(const Model& m);

} // namespace seamless::cli
