// SPDX-License-Identifier: MIT
// INTRACY step 3 (paper section 7): every marked patch of a sub-screen B is
// compared with B by hull (remark 1 of Prop. 11 in its primary-ray form: the
// hull of its projected control points), then its (s, t) intervals are
// narrowed (Theorem 10's question, by Bezier clipping of the subpatch the
// mark carries from its parent, mark.h), separated at the midpoints where a
// silhouette is possible (remark 3), bisected where they stay wide (covering
// method, section 5 remark 2); a patch whose intervals become empty is unmarked.
#pragma once

#include <seamless/render/scene/projection.h>
#include <seamless/render/scene/render_stats.h>
#include <seamless/render/subscreen/subscreen.h>

#include <vector>

namespace seamless {

class MarkNarrowing {
  public:
    explicit MarkNarrowing(const ProjectedScene& ps) : ps_(ps) {}

    // Step 3 for B: its marks stack.marks[B.offset, B.offset + B.count)
    // that may meet B's rays, narrowed, appended to stack.marks (their
    // subpatches to stack.coefs). A one-pixel B takes the hull comparison
    // alone (step 6 solves its marks).
    void narrow(MarkStack& stack, const SubScreen& B, RenderStats& st);

  private:
    static constexpr int kMaxBisections = 64; // per marked patch and sub-screen
    const ProjectedScene& ps_;
    std::vector<Mark> work_; // a mark's pieces still to narrow
};

} // namespace seamless
