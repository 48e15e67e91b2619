// SPDX-License-Identifier: MIT
// Sub-screens and their marks (subscreen.h).
#include <seamless/render/subscreen/subscreen.h>

namespace seamless {

MarkStack whole_marks(const ProjectedScene& ps) {
    MarkStack whole;
    whole.marks.reserve(ps.patches.size());
    for (size_t k = 0; k < ps.patches.size(); ++k) {
        const ProjectedPatch& pp = ps.patches[k];
        whole.marks.push_back(
            whole_patch_mark(static_cast<int>(k), pp.patch, pp.shape, pp.hull, whole.coefs));
    }
    return whole;
}

int split_subscreen(const SubScreen& B, SubScreen kids[4]) {
    const int w = B.x1 - B.x0 + 1, h = B.y1 - B.y0 + 1;
    const int xm = B.x0 + w / 2 - 1, ym = B.y0 + h / 2 - 1;
    const int cause = B.cause;
    int nk = 0;
    if (w > 1 && h > 1) {
        kids[nk++] = {B.x0, B.y0, xm, ym, 0, 0, 0, true, cause};
        kids[nk++] = {xm + 1, B.y0, B.x1, ym, 0, 0, 0, true, cause};
        kids[nk++] = {B.x0, ym + 1, xm, B.y1, 0, 0, 0, true, cause};
        kids[nk++] = {xm + 1, ym + 1, B.x1, B.y1, 0, 0, 0, true, cause};
    } else if (w > 1) {
        kids[nk++] = {B.x0, B.y0, xm, B.y1, 0, 0, 0, true, cause};
        kids[nk++] = {xm + 1, B.y0, B.x1, B.y1, 0, 0, 0, true, cause};
    } else {
        kids[nk++] = {B.x0, B.y0, B.x1, ym, 0, 0, 0, true, cause};
        kids[nk++] = {B.x0, ym + 1, B.x1, B.y1, 0, 0, 0, true, cause};
    }
    return nk;
}

} // namespace seamless
