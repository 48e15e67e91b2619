// SPDX-License-Identifier: MIT
// Topology and geometry checks of a triangle mesh, written independently of the
// tessellation code: duplicate positions, zero-area triangles, edge use and
// orientation, T-junctions (a vertex inside another triangle's edge), Euler
// characteristic.
#pragma once

#include <seamless/base/triangle_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

namespace seamless::test {

struct MeshReport {
    int duplicate_positions = 0; // pairs of vertices at the same point
    int zero_area = 0;           // triangles with a repeated index or zero area
    int border_edges = 0;        // edges of one triangle
    int nonmanifold_edges = 0;   // edges of more than two triangles
    int misoriented_edges = 0;   // edges of two triangles running the same way
    int t_junctions = 0;         // edges with a vertex strictly inside
    long long V = 0, E = 0, F = 0;
    std::string example; // the first T-junction found, for messages
    long long euler() const { return V - E + F; }
};

// free_overlaps: do not count a vertex of a border edge lying inside another
// border edge, i.e. free boundaries of the input that overlap (the teaspoon's
// sliver holes at its pinched ends, shared/models/README.md).
inline MeshReport analyse_mesh(const TriangleMesh& m, double d_max, bool t_junctions = true,
                               bool free_overlaps = false) {
    MeshReport r;
    // Duplicate positions.
    std::vector<Vec3> pos = m.positions;
    std::sort(pos.begin(), pos.end(), [](Vec3 a, Vec3 b) {
        return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
    });
    for (size_t i = 1; i < pos.size(); ++i)
        if (pos[i] == pos[i - 1]) ++r.duplicate_positions;
    // Triangles and edges.
    // Directed edges as (lo << 32 | hi) * 2 + (runs hi -> lo), sorted: each
    // undirected edge is one run.
    std::vector<std::uint64_t> directed;
    directed.reserve(3 * m.triangles.size());
    std::vector<char> used(m.positions.size(), 0);
    for (const auto& t : m.triangles) {
        const Vec3 a = m.positions[t[0]], b = m.positions[t[1]], c = m.positions[t[2]];
        if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2] || !(norm(cross(b - a, c - a)) > 0))
            ++r.zero_area;
        for (int k = 0; k < 3; ++k) {
            const int u = t[k], v = t[(k + 1) % 3];
            used[u] = 1;
            const std::uint64_t lo = std::min(u, v), hi = std::max(u, v);
            directed.push_back(((lo << 32) | hi) * 2 + (u > v ? 1 : 0));
        }
    }
    std::sort(directed.begin(), directed.end());
    std::vector<std::pair<int, int>> edges; // undirected, (lo, hi)
    std::vector<char> edge_border, border_vertex(m.positions.size(), 0);
    for (size_t i = 0; i < directed.size();) {
        size_t j = i;
        int fwd = 0, bwd = 0;
        while (j < directed.size() && directed[j] / 2 == directed[i] / 2)
            (directed[j++] % 2 ? bwd : fwd)++;
        const int total = fwd + bwd;
        if (total == 1)
            ++r.border_edges;
        else if (total > 2)
            ++r.nonmanifold_edges;
        else if (fwd != 1)
            ++r.misoriented_edges;
        edges.push_back({static_cast<int>(directed[i] / 2 >> 32),
                         static_cast<int>(directed[i] / 2 & 0xffffffffu)});
        edge_border.push_back(total == 1);
        if (total == 1) border_vertex[edges.back().first] = border_vertex[edges.back().second] = 1;
        i = j;
    }
    r.F = static_cast<long long>(m.triangles.size());
    r.E = static_cast<long long>(edges.size());
    r.V = std::count(used.begin(), used.end(), 1);
    if (!t_junctions || edges.empty()) return r;
    // T-junctions: a uniform grid of vertices, walked along every edge.
    double total_len = 0;
    for (const auto& key : edges)
        total_len += distance(m.positions[key.first], m.positions[key.second]);
    const double h = std::max(total_len / edges.size(), 1e-9 * d_max);
    auto cell = [h](Vec3 p) {
        return std::array<long long, 3>{static_cast<long long>(std::floor(p.x / h)),
                                        static_cast<long long>(std::floor(p.y / h)),
                                        static_cast<long long>(std::floor(p.z / h))};
    };
    auto key_of = [](long long x, long long y, long long z) {
        return (static_cast<std::uint64_t>(x) * 73856093ull) ^
               (static_cast<std::uint64_t>(y) * 19349663ull) ^
               (static_cast<std::uint64_t>(z) * 83492791ull);
    };
    std::vector<std::pair<std::uint64_t, int>> grid; // (cell key, vertex), sorted
    for (size_t i = 0; i < m.positions.size(); ++i) {
        if (!used[i]) continue;
        const auto c = cell(m.positions[i]);
        grid.push_back({key_of(c[0], c[1], c[2]), static_cast<int>(i)});
    }
    std::sort(grid.begin(), grid.end());
    // Cell key -> its run [begin, end) in grid: one hash lookup per cell.
    std::unordered_map<std::uint64_t, std::pair<int, int>> runs;
    runs.reserve(grid.size());
    for (size_t i = 0; i < grid.size();) {
        size_t j = i;
        while (j < grid.size() && grid[j].first == grid[i].first) ++j;
        runs.emplace(grid[i].first, std::pair<int, int>{static_cast<int>(i), static_cast<int>(j)});
        i = j;
    }
    const double tol = 1e-10 * d_max;
    std::vector<std::uint64_t> cells; // of one edge, deduplicated
    for (size_t ei = 0; ei < edges.size(); ++ei) {
        const auto& key = edges[ei];
        const Vec3 a = m.positions[key.first], b = m.positions[key.second];
        const Vec3 d = b - a;
        const double dd = dot(d, d);
        if (!(dd > 0)) continue;
        // A vertex within tol of the edge lies within tol of one piece of it
        // no longer than h, so in a cell meeting that piece's box grown by tol.
        const int steps = 1 + static_cast<int>(std::sqrt(dd) / h);
        cells.clear();
        for (int k = 0; k < steps; ++k) {
            const Vec3 p = a + (double(k) / steps) * d, q = a + (double(k + 1) / steps) * d;
            const auto lo = cell(
                Vec3{std::min(p.x, q.x) - tol, std::min(p.y, q.y) - tol, std::min(p.z, q.z) - tol});
            const auto hi = cell(
                Vec3{std::max(p.x, q.x) + tol, std::max(p.y, q.y) + tol, std::max(p.z, q.z) + tol});
            for (long long x = lo[0]; x <= hi[0]; ++x)
                for (long long y = lo[1]; y <= hi[1]; ++y)
                    for (long long z = lo[2]; z <= hi[2]; ++z) cells.push_back(key_of(x, y, z));
        }
        std::sort(cells.begin(), cells.end());
        cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
        bool found = false;
        for (size_t ci = 0; ci < cells.size() && !found; ++ci) {
            const auto run = runs.find(cells[ci]);
            if (run == runs.end()) continue;
            for (int g = run->second.first; g < run->second.second; ++g) {
                const int v = grid[g].second;
                if (v == key.first || v == key.second) continue;
                if (free_overlaps && edge_border[ei] && border_vertex[v]) continue;
                const Vec3 p = m.positions[v];
                const double t = dot(p - a, d) / dd;
                if (t <= 1e-9 || t >= 1 - 1e-9) continue;
                if (distance(p, a + t * d) <= tol) {
                    if (r.example.empty()) {
                        std::ostringstream os;
                        os.precision(17);
                        os << "vertex " << v << " (" << p.x << ", " << p.y << ", " << p.z
                           << ") inside edge " << key.first << " (" << a.x << ", " << a.y << ", "
                           << a.z << ") - " << key.second << " (" << b.x << ", " << b.y << ", "
                           << b.z << ") at " << t;
                        r.example = os.str();
                    }
                    found = true;
                    break;
                }
            }
        }
        if (found) ++r.t_junctions;
    }
    return r;
}

// Connected components of the triangles (sharing a vertex index).
inline int count_shells(const TriangleMesh& m) {
    std::vector<int> parent(m.positions.size());
    for (size_t i = 0; i < parent.size(); ++i) parent[i] = static_cast<int>(i);
    auto find = [&](int x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    };
    for (const auto& t : m.triangles)
        for (int k = 1; k < 3; ++k) parent[find(t[k])] = find(t[0]);
    std::vector<char> root(m.positions.size(), 0);
    int shells = 0;
    for (const auto& t : m.triangles) {
        const int r = find(t[0]);
        if (!root[r]) root[r] = 1, ++shells;
    }
    return shells;
}

// Border edges (of one triangle) whose both end points satisfy `where`.
template <class Where> int border_edges_where(const TriangleMesh& m, Where where) {
    std::vector<std::uint64_t> keys;
    for (const auto& t : m.triangles)
        for (int k = 0; k < 3; ++k) {
            const std::uint64_t a = std::min(t[k], t[(k + 1) % 3]),
                                b = std::max(t[k], t[(k + 1) % 3]);
            keys.push_back(a << 32 | b);
        }
    std::sort(keys.begin(), keys.end());
    int count = 0;
    for (size_t i = 0; i < keys.size();) {
        size_t j = i;
        while (j < keys.size() && keys[j] == keys[i]) ++j;
        if (j - i == 1 && where(m.positions[keys[i] >> 32]) &&
            where(m.positions[keys[i] & 0xffffffffu]))
            ++count;
        i = j;
    }
    return count;
}

} // namespace seamless::test
