// SPDX-License-Identifier: MIT
// INTRACY step 5 (shrink.h).
#include <seamless/render/subscreen/shrink.h>

namespace seamless {

PixelRect shrink_to_marks(const CameraFrame& frame, const PixelRect& B, const Mark* marks,
                          size_t n) {
    Interval ha = Interval::empty(), hb = Interval::empty();
    for (size_t k = 0; k < n; ++k) {
        const Mark& m = marks[k];
        if (m.pa.is_finite() && m.pb.is_finite()) {
            ha = hull(ha, m.pa);
            hb = hull(hb, m.pb);
            continue;
        }
        const IVec3& P = m.hull;
        if (!(P[2].lo() > 0)) return B; // crosses the eye plane: no projection hull
        ha = hull(ha, P[0] / P[2]);
        hb = hull(hb, P[1] / P[2]);
    }
    PixelRect r = B;
    while (r.x0 <= r.x1 && frame.screen_a(r.x0 + 0.5) < ha.lo()) ++r.x0;
    while (r.x1 >= r.x0 && frame.screen_a(r.x1 + 0.5) > ha.hi()) --r.x1;
    while (r.y0 <= r.y1 && frame.screen_b(r.y0 + 0.5) < hb.lo()) ++r.y0;
    while (r.y1 >= r.y0 && frame.screen_b(r.y1 + 0.5) > hb.hi()) --r.y1;
    return r;
}

} // namespace seamless
