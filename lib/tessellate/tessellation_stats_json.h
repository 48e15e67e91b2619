// SPDX-License-Identifier: MIT
// The statistics of a tessellation as the JSON object `seamless tessellate
// --stats` writes (docs/formats.md, "Statistics JSON"): one home for the
// CLI and the Python module.
#pragma once

#include <seamless/tessellate/tessellation_result.h>

#include <string>

namespace seamless {

// What the statistics do not know: where the model came from and went.
struct StatsSource {
    std::string model;
    std::string output; // empty: written as null (the mesh was not written to a file)
    double angle_degrees = 0;
};

// JSON text, indented by 2, without a final newline.
std::string tessellation_stats_json(const TessellationStats& s, const StatsSource& source);

} // namespace seamless
