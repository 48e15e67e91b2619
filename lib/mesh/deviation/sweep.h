// SPDX-License-Identifier: MIT
// Accuracy against run time (paper section 8): tessellate a model at
// tolerances scaled over decades and measure each mesh's deviation from the
// exact surfaces (deviation.h) beside its certified bound (tessellate/bounds/error_bound.h).
// Either the paper's planarity tolerances are scaled (eps1 = f * 0.001 d_max,
// eps2 = f * 0.02 d_max) or a deviation D = f * 0.001 d_max is requested
// (TessellationOptions::tolerance).
#pragma once

#include <seamless/mesh/deviation/deviation.h>
#include <seamless/model/model.h>
#include <seamless/tessellate/tessellation.h>

#include <functional>
#include <string>
#include <vector>

namespace seamless {

// One row of an accuracy-against-run-time sweep.
struct SweepRow {
    double factor = 0;      // of paper_tolerances(d_max), or of the tolerance 0.001 d_max
    double tolerance = 0;   // requested deviation (tolerance sweeps), model units
    TessellationStats tess; // triangles, seconds, max_error_bound, ...
    Deviation deviation;
    bool within_bound() const { return deviation.max() <= tess.max_error_bound; }
    // measured / bound: 1 for an exact bound.
    double tightness() const {
        return tess.max_error_bound > 0 ? deviation.max() / tess.max_error_bound : 0.0;
    }
};

struct SweepOptions {
    // false: scale the planarity tolerances; true: request D = factor * 0.001 d_max.
    bool tolerance = false;
    // factor = 10^(first_decade - k / steps_per_decade), k = 0 .. decades * steps_per_decade.
    double first_decade = 1; // start at factor 10
    int decades = 5;
    int steps_per_decade = 2;
    // Stop before a step whose predicted triangle count (the last count times
    // the last growth ratio) exceeds this.
    long long max_triangles = 2'000'000;
    // Tessellation threads (TessellationOptions::threads: the same mesh on any
    // count; seconds are per this count).
    int threads = 0;
    DeviationOptions deviation;
    // Called with each row as soon as it is measured (a sweep of a fine model
    // runs for tens of seconds: the CLI prints its rows as they come).
    std::function<void(const SweepRow&)> on_row;
};

std::vector<SweepRow> sweep_tolerances(const Model& model, const SweepOptions& options = {});

// The rows as a JSON array (one object per row: factor, tolerance, triangles,
// seconds, bound, surface_to_mesh, mesh_to_surface, same_parameter, ...).
std::string sweep_json(const std::vector<SweepRow>& rows);

} // namespace seamless
