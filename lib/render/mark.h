// SPDX-License-Identifier: MIT
// A marked patch of a sub-screen (paper section 7, INTRACY step 3): the patch,
// the parameter box that may still hold hits of the sub-screen's rays, and a
// camera-space enclosure of the patch over that box.
#pragma once

#include <seamless/spline/enclosure.h>

namespace seamless {

struct Mark {
    int patch;
    ParamBox box;
    IVec3 hull; // camera-space enclosure of the patch over box (or a superset)
};

} // namespace seamless
