// SPDX-License-Identifier: MIT
#include <seamless/tessellate/trimmed/face_surface.h>

#include <algorithm>
#include <cmath>

namespace seamless {

namespace {

// t in [lo, hi]: as is; else moved by whole periods hi - lo into it.
double wrap(double t, double lo, double hi) {
    if (t >= lo && t <= hi) return t;
    const double period = hi - lo;
    return lo + (t - lo - period * std::floor((t - lo) / period));
}

} // namespace

FaceSurface::FaceSurface(const BSplineSurface& s) : s_(&s) {
    const double tiny = 1e-12 * control_box(s).max_extent();
    closed_u_ = closed_v_ = true;
    for (int j = 0; j < s.size_v; ++j)
        closed_u_ = closed_u_ && distance(s.point(0, j), s.point(s.size_u - 1, j)) <= tiny;
    for (int i = 0; i < s.size_u; ++i)
        closed_v_ = closed_v_ && distance(s.point(i, 0), s.point(i, s.size_v - 1)) <= tiny;
}

SurfacePoint FaceSurface::at(Vec3 uv) const {
    const double u = closed_u_ ? wrap(uv.x, s_->u_min(), s_->u_max()) : uv.x;
    const double v = closed_v_ ? wrap(uv.y, s_->v_min(), s_->v_max()) : uv.y;
    const double uc = std::clamp(u, s_->u_min(), s_->u_max()),
                 vc = std::clamp(v, s_->v_min(), s_->v_max());
    SurfacePoint p = evaluate(*s_, uc, vc);
    // Beyond the domain, to first order: exact for planes, and close for
    // pcurves a little outside it (within the file's tolerance).
    if (uc != u || vc != v) p.point += (u - uc) * p.du + (v - vc) * p.dv;
    return p;
}

} // namespace seamless
