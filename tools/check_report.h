// SPDX-License-Identifier: MIT
// The check command's output: a CheckReport as text or as JSON (docs/check.md).
#pragma once

#include <seamless/mesh/check/check.h>

#include <ostream>
#include <string>

namespace seamless::cli {

// Text report: counts, then the first `max_listed` entries of each defect list.
void print_check_report(std::ostream& os, const CheckReport& report, size_t max_listed = 10);

// The whole report as JSON; defect lists are cut at `max_listed` entries each
// (their full counts are always given).
std::string check_report_json(const CheckReport& report, int max_listed = 1000);

} // namespace seamless::cli
