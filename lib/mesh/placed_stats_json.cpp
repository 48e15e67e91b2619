// SPDX-License-Identifier: MIT
#include <seamless/mesh/io/placed_mesh.h>
#include <seamless/mesh/placed_stats_json.h>

#include <nlohmann/json.hpp>

namespace seamless {

std::string placed_stats_json(const TessellationStats& s, const StatsSource& source,
                              const TriangleMesh& mesh, const Model& model) {
    // The tessellation's object is sorted by key, as nlohmann keeps it: adding
    // members and dumping again keeps its text.
    nlohmann::json js = nlohmann::json::parse(tessellation_stats_json(s, source));
    const PlacedCounts placed = placed_counts(mesh, model);
    js["placed_triangles"] = placed.triangles;
    js["placed_vertices"] = placed.vertices;
    if (!placed.parts.empty()) {
        nlohmann::json parts = nlohmann::json::array();
        for (size_t k = 0; k < placed.parts.size(); ++k)
            parts.push_back({{"name", model.assembly.parts[k].name},
                             {"instances", placed.parts[k].instances},
                             {"triangles", placed.parts[k].triangles},
                             {"vertices", placed.parts[k].vertices}});
        js["parts"] = std::move(parts);
    }
    return js.dump(2);
}

} // namespace seamless
