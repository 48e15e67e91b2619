// SPDX-License-Identifier: MIT
// INTRACY step 5 (paper section 7): a sub-screen B shrinks to the hull of the
// projections of its marked patches; the rest of B is background, certainly.
#pragma once

#include <seamless/render/scene/camera.h>
#include <seamless/render/scene/canvas.h>
#include <seamless/render/subscreen/mark.h>

#include <cstddef>

namespace seamless {

// The pixels of B whose centres lie in the hull of the screen enclosures of
// its n marks: B itself where a mark may cross the eye plane (no projection
// hull), empty() where none.
PixelRect shrink_to_marks(const CameraFrame& frame, const PixelRect& B, const Mark* marks,
                          size_t n);

} // namespace seamless
