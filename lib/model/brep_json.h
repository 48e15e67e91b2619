// SPDX-License-Identifier: MIT
// The "brep" object of the version-2 JSON model format (docs/formats.md,
// "Model: JSON, version 2 (B-rep)"): read with the model reader's field reader
// (json_fields.h), written by to_json. Internal to model_json.cpp, like
// json_fields.h, whose nlohmann types it exposes.
#pragma once

#include <seamless/model/json_fields.h>
#include <seamless/model/model.h>

#include <ostream>

namespace seamless {

// Reads the B-rep object j (field "brep") into b. Checks the JSON's shape,
// the types and the sizes against `limits` before allocating for them; the
// B-rep's consistency is validate_brep's, after the whole model is read.
void read_brep_json(const JsonFields& r, const Json& j, const ModelLimits& limits, BRep& b);

// Writes b as the value of "brep" (an object, indented one level below the
// model's members), numbers with 17 significant digits.
void write_brep_json(std::ostream& os, const BRep& b);

// The "assembly" object (assembly_json.cpp): read into a, checked for its
// JSON shape and sizes; validate_assembly checks it against the B-rep.
void read_assembly_json(const JsonFields& r, const Json& j, const ModelLimits& limits, Assembly& a);
void write_assembly_json(std::ostream& os, const Assembly& a);

} // namespace seamless
