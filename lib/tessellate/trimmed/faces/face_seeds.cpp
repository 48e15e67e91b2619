// SPDX-License-Identifier: MIT
#include <seamless/base/check.h>
#include <seamless/tessellate/trimmed/faces/face_seeds.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace seamless {

void insert_seeds(const FaceSurface& s, const FaceDomain& earlier, FaceDomain& d,
                  ConstrainedTriangulation& cdt) {
    std::vector<std::array<double, 2>> old;
    for (int i = 0; i < earlier.boundary_points; ++i)
        old.push_back({earlier.uv[i].x, earlier.uv[i].y});
    std::sort(old.begin(), old.end());
    // New boundary points, each with the square of its shorter segment's length.
    std::vector<std::pair<Vec3, double>> fresh;
    std::vector<double> reach(d.boundary_points, INFINITY);
    for (const auto& g : d.segments) {
        const double l2 = dot(d.scaled[g[1]] - d.scaled[g[0]], d.scaled[g[1]] - d.scaled[g[0]]);
        for (int k : g) reach[k] = std::min(reach[k], l2);
    }
    for (int i = 0; i < d.boundary_points; ++i)
        if (!std::binary_search(old.begin(), old.end(),
                                std::array<double, 2>{d.uv[i].x, d.uv[i].y}))
            fresh.push_back({d.scaled[i], reach[i]});
    int near = 0;
    for (int i = earlier.boundary_points; i < earlier.size(); ++i) {
        const Vec3 at{earlier.uv[i].x * d.su, earlier.uv[i].y * d.sv, 0};
        if (std::any_of(fresh.begin(), fresh.end(), [&](const std::pair<Vec3, double>& f) {
                return dot(at - f.first, at - f.first) < f.second;
            }))
            continue;
        const int index = cdt.insert(at, 0, near);
        if (index < 0) continue;
        SEAMLESS_CHECK(index == d.size(), "the triangulation numbers inserted points in order");
        d.add_interior(s, at, earlier.uv[i]);
        near = index;
    }
}

} // namespace seamless
