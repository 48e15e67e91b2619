// SPDX-License-Identifier: MIT
// The options of every subcommand that reads a model (STEP/IGES trimmed
// faces, the STEP/IGES reader's limits), and printing the reader's warnings.
#pragma once

#include <seamless/model/model.h>

#include <CLI/CLI.hpp>

#include <cstdint>
#include <optional>
#include <string>

namespace seamless::cli {

// Adds --skip-trimmed and --untrimmed to `cmd`, filling `options.trimmed`,
// and the reader's limits (add_reader_limits).
void add_model_options(CLI::App* cmd, ModelLoadOptions& options);

// Adds --reader-time-limit SECONDS and --reader-memory-limit BYTES to `cmd`,
// filling options.reader_time_limit and options.reader_memory_limit.
void add_reader_limits(CLI::App* cmd, ModelLoadOptions& options);

// "4096", "512K", "64M", "4G", "1T" (powers of 1024) as bytes; none when
// malformed or above 2^62.
std::optional<std::uint64_t> parse_bytes(const std::string& text);

// One "warning: ..." line on stderr per Model::warnings entry.
void print_warnings(const Model& m);

} // namespace seamless::cli
