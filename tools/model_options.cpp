// SPDX-License-Identifier: MIT
#include "model_options.h"

#include <iostream>

namespace seamless::cli {

void add_model_options(CLI::App* cmd, ModelLoadOptions& options) {
    auto* skip = cmd->add_flag_callback(
        "--skip-trimmed", [&options] { options.trimmed = TrimmedFaces::skip; },
        "STEP/IGES: leave trimmed faces out (default: read them as trimmed B-rep faces)");
    auto* whole = cmd->add_flag_callback(
        "--untrimmed", [&options] { options.trimmed = TrimmedFaces::whole_surface; },
        "STEP/IGES: take the whole underlying surfaces of trimmed faces");
    skip->excludes(whole);
}

void print_warnings(const Model& m) {
    for (const std::string& w : m.warnings) std::cerr << "warning: " << w << "\n";
}

} // namespace seamless::cli
