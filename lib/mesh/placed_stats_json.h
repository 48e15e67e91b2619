// SPDX-License-Identifier: MIT
// The statistics JSON of `seamless tessellate --stats` and the Python
// module's Mesh.stats (docs/formats.md, "Statistics JSON"): the
// tessellation's figures (tessellation_stats_json.h) with those of the
// model as placed (io/placed_mesh.h, placed_counts). Outside io/: the fuzz
// harnesses' readers link io/ without the tessellation.
#pragma once

#include <seamless/base/triangle_mesh.h>
#include <seamless/model/model.h>
#include <seamless/tessellate/tessellation_stats_json.h>

#include <string>

namespace seamless {

// JSON text, indented by 2, without a final newline: `s`'s fields, then
// placed_triangles and placed_vertices of `mesh` (the tessellation of
// `model`) placed and, for a model with a tree, `parts`: per part its name,
// instances and one instance's triangles and vertices.
std::string placed_stats_json(const TessellationStats& s, const StatsSource& source,
                              const TriangleMesh& mesh, const Model& model);

} // namespace seamless
