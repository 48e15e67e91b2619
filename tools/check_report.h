// SPDX-License-Identifier: MIT
// The check command's text output: a CheckReport as text (docs/check.md); the
// JSON is the library's (mesh/check/check_json.h).
#pragma once

#include <seamless/mesh/check/check.h>

#include <ostream>

namespace seamless::cli {

// Text report: counts, then the first `max_listed` entries of each defect
// list; with `mesh` (the mesh checked) holding face ids, each entry names
// the faces and parts it lies on, and the faces with defects are listed.
void print_check_report(std::ostream& os, const CheckReport& report, size_t max_listed = 10,
                        const TriangleMesh* mesh = nullptr);

} // namespace seamless::cli
