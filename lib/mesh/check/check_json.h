// SPDX-License-Identifier: MIT
// The watertightness check's report as JSON (docs/check.md, `seamless check
// --json`), beside sweep_json (deviation/sweep.h).
#pragma once

#include <seamless/mesh/check/check.h>

#include <string>

namespace seamless {

// The whole report as a JSON object, indented by 2; defect lists are cut at
// `max_listed` entries each ("listed"), their full counts always given ("count").
std::string check_report_json(const CheckReport& report, int max_listed = 1000);

} // namespace seamless
