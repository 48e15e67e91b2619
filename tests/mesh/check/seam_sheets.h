// SPDX-License-Identifier: MIT
// Test meshes for seam cracks, built directly (no tessellator): two sheets of
// the surface z = 0.3 sin(2x), one over x in [-1, 0], one over [0, 1], meeting
// along x = 0, each made of columns of triangles between vertical polylines.
#pragma once

#include <seamless/base/triangle_mesh.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace seamless::test {

// k / n for k = 0..n.
inline std::vector<double> divisions(int n) {
    std::vector<double> ys;
    for (int k = 0; k <= n; ++k) ys.push_back(static_cast<double>(k) / n);
    return ys;
}

// The sorted union of two lists of parameters.
inline std::vector<double> merged(std::vector<double> a, const std::vector<double>& b) {
    a.insert(a.end(), b.begin(), b.end());
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
    return a;
}

// One sheet: polylines at xs[i] with parameters ys[i] (each from 0 to 1); the
// strip between neighbouring polylines is triangulated by merging their points
// by y, oriented with normal +z. Each point is (x + shift, y, 0.3 sin(2x)), a
// vertex of its own (two sheets share no index; welding joins equal positions).
inline void add_sheet(TriangleMesh& m, const std::vector<double>& xs,
                      const std::vector<std::vector<double>>& ys, double shift = 0) {
    std::vector<std::vector<int>> ids(xs.size());
    for (size_t i = 0; i < xs.size(); ++i)
        for (double y : ys[i]) {
            ids[i].push_back(m.vertex_count());
            m.positions.push_back({xs[i] + shift, y, 0.3 * std::sin(2 * xs[i])});
        }
    for (size_t i = 0; i + 1 < xs.size(); ++i) {
        const auto &L = ids[i], &R = ids[i + 1];
        const auto &yl = ys[i], &yr = ys[i + 1];
        size_t a = 0, b = 0;
        while (a + 1 < L.size() || b + 1 < R.size()) {
            const bool left = b + 1 == R.size() || (a + 1 < L.size() && yl[a + 1] <= yr[b + 1]);
            if (left) {
                m.triangles.push_back({L[a], R[b], L[a + 1]});
                ++a;
            } else {
                m.triangles.push_back({L[a], R[b], R[b + 1]});
                ++b;
            }
        }
    }
}

// Sheet over [x0, x1] with `columns` columns, every polyline divided in `rows`,
// except the one at x = 0 (the seam), which has `seam` parameters.
inline void add_seam_sheet(TriangleMesh& m, double x0, double x1, int columns, int rows,
                           const std::vector<double>& seam, double shift = 0) {
    std::vector<double> xs;
    std::vector<std::vector<double>> ys;
    for (int i = 0; i <= columns; ++i) {
        const double x = x0 + (x1 - x0) * i / columns;
        xs.push_back(x);
        ys.push_back(x == 0 ? seam : divisions(rows));
    }
    add_sheet(m, xs, ys, shift);
}

// Sheet A over [-1, 0], 10 rows (edges 0.1 long along the seam); sheet B over
// [0, 1], 7 rows (edges 1/7), shifted by `gap` in x. The seam polylines are
// `seam_a` and `seam_b`.
inline TriangleMesh two_sheets(const std::vector<double>& seam_a, const std::vector<double>& seam_b,
                               double gap, int rows_a = 10, int rows_b = 7) {
    TriangleMesh m;
    add_seam_sheet(m, -1, 0, 10, rows_a, seam_a);
    add_seam_sheet(m, 0, 1, 7, rows_b, seam_b, gap);
    return m;
}

} // namespace seamless::test
