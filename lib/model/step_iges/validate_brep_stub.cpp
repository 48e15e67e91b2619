// SPDX-License-Identifier: MIT
// TEMPORARY (branch i28-occ): a no-op validate_brep until lib/model/brep.cpp
// (branch i28-json) defines it. Delete this file when merging that branch.
#include <seamless/model/model.h>

namespace seamless {

__attribute__((weak)) void validate_brep(const Model&, const std::string&, const ModelLimits&) {}

} // namespace seamless
