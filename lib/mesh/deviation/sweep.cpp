// SPDX-License-Identifier: MIT
#include <seamless/mesh/deviation/sweep.h>

#include <seamless/mesh/deviation/brep_deviation.h>
#include <seamless/tessellate/trimmed/brep_tessellation.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace seamless {

std::vector<SweepRow> sweep_tolerances(const Model& model, const SweepOptions& options) {
    std::vector<SweepRow> rows;
    const double dm = d_max(model);
    const int steps = std::max(1, options.steps_per_decade);
    for (int k = 0; k <= options.decades * steps; ++k) {
        const double factor = std::pow(10.0, options.first_decade - double(k) / steps);
        if (!rows.empty()) {
            // Triangles grow like 1/eps (deviation ~ h^2): predict from the last step.
            double ratio = std::pow(10.0, 1.0 / steps);
            if (rows.size() >= 2 && rows[rows.size() - 2].tess.triangles > 0)
                ratio = std::max(ratio, double(rows.back().tess.triangles) /
                                            rows[rows.size() - 2].tess.triangles);
            if (rows.back().tess.triangles * ratio > double(options.max_triangles)) break;
        }
        TessellationOptions topt;
        topt.threads = options.threads;
        // The prediction above can be short: the library's budget, at least
        // twice the sweep's, backs it.
        topt.max_triangles = std::max<std::int64_t>(topt.max_triangles, 2 * options.max_triangles);
        SweepRow row;
        row.factor = factor;
        if (!model.brep.empty()) {
            // Trimmed faces have no planarity test: D = factor * their
            // default deviation, 0.001 of the diagonal.
            row.tolerance = factor * brep_deviation(model, TessellationOptions{});
            topt.tolerance = row.tolerance;
        } else if (options.tolerance) {
            row.tolerance = factor * paper_tolerances(dm).eps1;
            topt.tolerance = row.tolerance;
        } else {
            const PlanarityTolerances e = paper_tolerances(dm, factor);
            topt.eps1 = e.eps1;
            topt.eps2 = e.eps2;
        }
        const Tessellation t = tessellate(model, topt);
        row.tess = t.stats;
        if (model.brep.empty()) {
            row.deviation = measure_deviation(model, t, options.deviation);
        } else {
            BRepDeviationOptions bo;
            bo.threads = options.deviation.threads;
            row.deviation = measure_brep_deviation(model, t.mesh, bo);
        }
        rows.push_back(row);
        if (options.on_row) options.on_row(rows.back());
    }
    return rows;
}

std::string sweep_json(const std::vector<SweepRow>& rows) {
    nlohmann::json a = nlohmann::json::array();
    for (const SweepRow& r : rows) {
        const Deviation& d = r.deviation;
        a.push_back({{"factor", r.factor},
                     {"tolerance", r.tolerance},
                     {"eps1", r.tess.eps1},
                     {"eps2", r.tess.eps2},
                     {"triangles", r.tess.triangles},
                     {"subpatches", r.tess.subpatches},
                     {"seconds", r.tess.seconds},
                     {"bound", r.tess.max_error_bound},
                     {"above_tolerance", r.tess.above_tolerance},
                     {"surface_to_mesh", d.surface_to_mesh.max},
                     {"surface_to_mesh_rms", d.surface_to_mesh.rms},
                     {"mesh_to_surface", d.mesh_to_surface.max},
                     {"mesh_to_surface_rms", d.mesh_to_surface.rms},
                     {"same_parameter", d.mesh_same_parameter.max},
                     {"measured", d.max()},
                     {"measure_seconds", d.seconds},
                     {"within_bound", r.within_bound()}});
    }
    return a.dump(2) + "\n";
}

} // namespace seamless
