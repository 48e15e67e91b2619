// SPDX-License-Identifier: MIT
// The small B-rep test models (model/brep_test_models.h, about 10 units
// across) tessellated at a deviation of 0.05, for the tests of what is
// written from them.
#pragma once

#include "model/brep_test_models.h"

#include <seamless/tessellate/tessellation.h>

namespace seamless::test {

inline TriangleMesh tessellated(const Model& m) {
    TessellationOptions opt;
    opt.tolerance = 0.05;
    return tessellate(m, opt).mesh;
}

} // namespace seamless::test
