// SPDX-License-Identifier: MIT
// The B-rep's "same parameter" convention checked on what the reader
// produced: at samples of every coedge, the face's surface at pcurve(t)
// against the edge's curve at t.
#pragma once

#include <seamless/model/model.h>

#include <string>

namespace seamless::step_iges {

// Largest distance |S(pcurve(t)) - curve(t)| at samples of the coedge's
// edge range (a degenerate edge: against its vertex).
double coedge_gap(const Model& m, int face, const BRepCoedge& c);

// Raises the tolerance of each edge whose gap exceeds it (with a slack of
// 1e-3 of the tolerance) to 1.25 times the gap, and warns naming the faces and edges
// and the figures. Returns the largest gap found.
double check_gaps(Model& m, const std::string& file);

} // namespace seamless::step_iges
