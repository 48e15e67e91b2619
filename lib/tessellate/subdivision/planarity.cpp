// SPDX-License-Identifier: MIT
#include <seamless/tessellate/subdivision/planarity.h>

#include <seamless/base/segment_distance.h>

#include <algorithm>

namespace seamless {

namespace {

// Distance of p to the infinite line through a and b (a != b).
double point_line_distance(Vec3 p, Vec3 a, Vec3 b) {
    const Vec3 d = b - a;
    return norm(cross(p - a, d)) / norm(d);
}

double curve_deviation(const BezierPatch& b, bool along_u, int fixed) {
    const int n = along_u ? b.p : b.q;
    auto pt = [&](int k) { return along_u ? b.point(k, fixed) : b.point(fixed, k); };
    const Vec3 a = pt(0), e = pt(n);
    double dev = 0;
    for (int k = 1; k < n; ++k) dev = std::max(dev, point_segment_distance(pt(k), a, e));
    return dev;
}

} // namespace

Planarity planarity(const BezierPatch& b) {
    Planarity r;
    const Vec3 c[4] = {b.corner(0), b.corner(1), b.corner(2), b.corner(3)};
    // Section 6: "the plane of any three corner points". All four triples are
    // tried; a sliver triple (area below 1e-12 of the corners' squared spread)
    // defines no plane and is skipped, so a pole never divides by zero.
    static constexpr int kTriples[4][3] = {{0, 1, 2}, {1, 2, 3}, {2, 3, 0}, {3, 0, 1}};
    double spread2 = 0;
    int far_a = 0, far_b = 0;
    for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j) {
            const Vec3 d = c[j] - c[i];
            if (dot(d, d) > spread2) {
                spread2 = dot(d, d);
                far_a = i;
                far_b = j;
            }
        }
    bool any_plane = false;
    double plane = 0;
    for (const auto& tr : kTriples) {
        const Vec3 n = cross(c[tr[1]] - c[tr[0]], c[tr[2]] - c[tr[0]]);
        const double len = norm(n);
        if (!(len > 1e-12 * spread2)) continue;
        any_plane = true;
        const Vec3 u = n / len;
        for (int i = 0; i <= b.p; ++i)
            for (int j = 0; j <= b.q; ++j)
                plane = std::max(plane, std::abs(dot(b.point(i, j) - c[tr[0]], u)));
    }
    if (!any_plane) {
        // Collinear or coincident corners: all control points must lie near that
        // line (or point), which implies the plane test for every plane through it.
        for (int i = 0; i <= b.p; ++i)
            for (int j = 0; j <= b.q; ++j) {
                const Vec3 x = b.point(i, j);
                plane = std::max(plane, spread2 > 0 ? point_line_distance(x, c[far_a], c[far_b])
                                                    : distance(x, c[0]));
            }
    }
    r.plane = plane;
    r.boundary = std::max({curve_deviation(b, true, 0), curve_deviation(b, true, b.q),
                           curve_deviation(b, false, 0), curve_deviation(b, false, b.p)});
    return r;
}

double flatness_u(const BezierPatch& b) {
    double f = 0;
    for (int j = 0; j <= b.q; ++j) f = std::max(f, curve_deviation(b, true, j));
    return f;
}

double flatness_v(const BezierPatch& b) {
    double f = 0;
    for (int i = 0; i <= b.p; ++i) f = std::max(f, curve_deviation(b, false, i));
    return f;
}

} // namespace seamless
