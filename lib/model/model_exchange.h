// SPDX-License-Identifier: MIT
// The form in which the STEP/IGES reader's process hands its model to the
// library (step_iges.h): every member of Model in a compact binary form,
// doubles as their bits and strings as their bytes, so that the caller's
// model is the reader's bit for bit (names with bytes that are not UTF-8
// included, which JSON cannot carry). It is not a file format: both ends are
// one build, so it has the machine's byte order and a version tag only
// against a stale reader. docs/formats.md ("STEP and IGES: the reader
// process") documents it.
//
// One writer and one reader for the whole Model: a member added to Model is
// added to both, in the model_exchange files (model_exchange_codec.h), and
// its test (model_exchange_test) fails until it is.
#pragma once

#include <seamless/model/model.h>

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

namespace seamless {

std::string write_model_exchange(const Model& m);
// The size of write_model_exchange(m), without writing it.
std::uint64_t model_exchange_size(const Model& m);
// The same bytes handed to `sink` in pieces, the large arrays straight from
// the model (the reader's process answers this way: the whole form is never
// held). Stops at the first piece the sink refuses, and returns false then.
bool write_model_exchange(const Model& m,
                          const std::function<bool(const char*, std::size_t)>& sink);

// Trusts nothing: a hostile file may have made the reader's process misbehave
// (tests/fuzz/fuzz_model_exchange.cpp). Every count is checked against the
// bytes left and against `limits` before anything is allocated for it, every
// surface and curve by validate_surface and validate_curve, every B-rep index
// against its list, so that no later stage reads out of bounds. The geometric
// checks of validate_brep (loops closed in (u,v), pcurves inside their
// surface's domain), which the reader's process ran on this same model before
// writing it, are not repeated: they alone would take most of the boundary's
// budget, or more (docs/results/step_iges_boundary.md). Throws
// InputError naming `file` and the field ("exchange.surfaces[3].knots_u: ...").
Model read_model_exchange(std::string_view bytes, const std::string& file,
                          const ModelLimits& limits = {});

} // namespace seamless
