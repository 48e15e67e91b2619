// SPDX-License-Identifier: MIT
// A render's statistics as the JSON object `seamless render --stats` writes
// (docs/formats.md, "Statistics JSON"): one home for the CLI and the Python
// module.
#pragma once

#include <seamless/render/scene/render_stats.h>

#include <string>

namespace seamless {

// JSON text, indented by 2, without a final newline.
std::string render_stats_json(const RenderStats& st);

} // namespace seamless
