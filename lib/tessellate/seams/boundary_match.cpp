// SPDX-License-Identifier: MIT
// Boundaries shared by patches (shared_edges.h): patch edges matched by their
// control polygons, the model's global edges and collapsed edges.
#include <seamless/base/disjoint_sets.h>
#include <seamless/tessellate/seams/shared_edges.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace seamless {
namespace {

// Largest deviation between two edges' control polygons (points and weights),
// forwards or with the second reversed; infinity when the orders differ.
double polygon_deviation(const BezierPatch& A, int ea, const BezierPatch& B, int eb, bool reverse) {
    const int n = edge_order(A, ea);
    if (edge_order(B, eb) != n) return std::numeric_limits<double>::infinity();
    double dev = 0;
    for (int k = 0; k <= n; ++k) {
        const HPoint a = edge_control(A, ea, k), b = edge_control(B, eb, reverse ? n - k : k);
        dev = std::max({dev, distance(a.point(), b.point()), std::abs(a.w - b.w)});
    }
    return dev;
}

} // namespace

int edge_order(const BezierPatch& b, int e) {
    return (e == 0 || e == 2) ? b.p : b.q;
}

HPoint edge_control(const BezierPatch& b, int e, int k) {
    switch (e) {
    case 0:
        return b.at(k, 0);
    case 1:
        return b.at(b.p, k);
    case 2:
        return b.at(k, b.q);
    default:
        return b.at(0, k);
    }
}

void edge_grid_point(int e, int x, int& s, int& t) {
    switch (e) {
    case 0:
        s = x, t = 0;
        break;
    case 1:
        s = kParamOne, t = x;
        break;
    case 2:
        s = x, t = kParamOne;
        break;
    default:
        s = 0, t = x;
        break;
    }
}

BoundaryMatch match_boundaries(const std::vector<BezierPatch>& patches, double tol) {
    const int np = static_cast<int>(patches.size());
    BoundaryMatch m;
    m.edge_group.assign(4 * np, -1);
    m.edge_reversed.assign(4 * np, 0);
    m.collapsed.assign(4 * np, 0);

    // Collapsed edges (poles) and the sweep keys of the others.
    std::vector<int> order;
    std::vector<double> key(4 * np, 0);
    for (int pe = 0; pe < 4 * np; ++pe) {
        const BezierPatch& b = patches[pe / 4];
        const int e = pe % 4, n = edge_order(b, e);
        const Vec3 first = edge_control(b, e, 0).point();
        bool collapsed = true;
        for (int k = 1; k <= n && collapsed; ++k)
            collapsed = distance(edge_control(b, e, k).point(), first) <= tol;
        m.collapsed[pe] = collapsed;
        if (collapsed) {
            ++m.collapsed_edges;
            continue;
        }
        key[pe] = std::min(first.x, edge_control(b, e, n).point().x);
        order.push_back(pe);
    }
    std::sort(order.begin(), order.end(), [&](int a, int b) { return key[a] < key[b]; });
    DisjointSets edges(4 * static_cast<size_t>(np));
    for (size_t i = 0; i < order.size(); ++i)
        for (size_t j = i + 1; j < order.size() && key[order[j]] - key[order[i]] <= tol; ++j) {
            const int a = order[i], b = order[j];
            const BezierPatch &A = patches[a / 4], &B = patches[b / 4];
            if (polygon_deviation(A, a % 4, B, b % 4, false) <= tol ||
                polygon_deviation(A, a % 4, B, b % 4, true) <= tol)
                edges.unite(a, b);
        }
    std::vector<int> group_of_root(4 * np, -1);
    for (int pe = 0; pe < 4 * np; ++pe) {
        if (m.collapsed[pe]) continue;
        const int root = edges.find(pe);
        if (group_of_root[root] < 0) {
            group_of_root[root] = static_cast<int>(m.group_ref.size());
            m.group_ref.push_back(pe); // the smallest member: the reference
            m.group_size.push_back(0);
        }
        const int g = group_of_root[root];
        m.edge_group[pe] = g;
        ++m.group_size[g];
        const int ref = m.group_ref[g];
        if (ref != pe) {
            const BezierPatch &A = patches[ref / 4], &B = patches[pe / 4];
            m.edge_reversed[pe] = polygon_deviation(A, ref % 4, B, pe % 4, true) <
                                  polygon_deviation(A, ref % 4, B, pe % 4, false);
        }
    }
    for (int n : m.group_size)
        if (n >= 2) ++m.shared_edges;

    // Weld corners by position (sweep in x).
    std::vector<Vec3> corners(4 * np);
    for (int c = 0; c < 4 * np; ++c) corners[c] = patches[c / 4].corner(c % 4);
    std::vector<int> by_x(4 * np);
    std::iota(by_x.begin(), by_x.end(), 0);
    std::sort(by_x.begin(), by_x.end(), [&](int a, int b) { return corners[a].x < corners[b].x; });
    DisjointSets welded(4 * static_cast<size_t>(np));
    for (size_t i = 0; i < by_x.size(); ++i)
        for (size_t j = i + 1; j < by_x.size() && corners[by_x[j]].x - corners[by_x[i]].x <= tol;
             ++j)
            if (distance(corners[by_x[i]], corners[by_x[j]]) <= tol) welded.unite(by_x[i], by_x[j]);
    m.corner_root.resize(4 * np);
    for (int c = 0; c < 4 * np; ++c) m.corner_root[c] = welded.find(c);
    return m;
}

} // namespace seamless
