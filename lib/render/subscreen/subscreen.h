// SPDX-License-Identifier: MIT
// The sub-screens B of INTRACY (paper section 7) on a part's stack, with
// their marked patches (mark.h) in one arena shared along the stack.
#pragma once

#include <seamless/render/scene/canvas.h>
#include <seamless/render/scene/projection.h>
#include <seamless/render/scene/render_stats.h>
#include <seamless/render/subscreen/mark.h>

#include <cstddef>
#include <vector>

namespace seamless {

// The marks of the sub-screens on the stack and their subpatches, appended
// to and truncated in the order of the stack (nothing allocated once grown):
// a sub-screen's marks are marks[offset, offset + count).
struct MarkStack {
    std::vector<Mark> marks;
    SubpatchArena coefs;
};

// Every patch's whole-patch mark and its subpatch (whole_patch_mark, in
// patch order), made once per render: each part starts from a copy.
MarkStack whole_marks(const ProjectedScene& ps);

struct SubScreen {
    int x0, y0, x1, y1;    // inclusive pixel range
    size_t offset, count;  // its marks in the MarkStack
    size_t coef_end;       // end of its marks' subpatches in the MarkStack's coefs
    bool attempt;          // try step 7 (false: its parent's intensity was far too wide)
    int cause;             // why its nearest attempting ancestor split (RenderStats::SplitCause)
    long long family = -1; // the same for the children of one parent (SharedMarks::reset)

    PixelRect rect() const { return {x0, y0, x1, y1}; }
    long long pixel_count() const { return rect().count(); }
    bool thin() const { return x0 == x1 && y0 == y1; } // one pixel
};

// The screen ranges [a] and [b] of the pixel centres of columns x0..x1 and rows y0..y1.
inline Interval screen_a(const CameraFrame& f, int x0, int x1) {
    return {f.screen_a(x0 + 0.5), f.screen_a(x1 + 0.5)};
}
inline Interval screen_b(const CameraFrame& f, int y0, int y1) {
    return {f.screen_b(y0 + 0.5), f.screen_b(y1 + 0.5)};
}

// Step 10 (remark 3): B's pixels split into four, or two where B is one
// pixel wide or high, into kids (their other fields to be set by the
// caller); returns how many.
int split_subscreen(const SubScreen& B, SubScreen kids[4]);

} // namespace seamless
