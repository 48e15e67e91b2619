// SPDX-License-Identifier: MIT
#include <seamless/base/disjoint_sets.h>
#include <seamless/tessellate/surface_orientation.h>

#include <algorithm>
#include <cstdint>
#include <unordered_map>

namespace seamless {
namespace {

struct EdgeUse {
    int surface = -1, count = 0;
    bool forward = false; // the first use runs from the smaller vertex index
    bool mixed = false;   // used by more than one other surface or more than twice
    int other = -1;
    bool other_forward = false;
};

// Union-find with parity: flip(x) = parity(x) xor flip(root).
struct ParitySets {
    std::vector<int> parent;
    std::vector<char> parity;
    explicit ParitySets(int n) : parent(n), parity(n, 0) {
        for (int i = 0; i < n; ++i) parent[i] = i;
    }
    std::pair<int, char> find(int x) {
        char p = 0;
        int r = x;
        while (parent[r] != r) {
            p ^= parity[r];
            r = parent[r];
        }
        // Path compression keeping parities relative to the root.
        char q = p;
        while (parent[x] != x) {
            const int next = parent[x];
            const char px = parity[x];
            parent[x] = r;
            parity[x] = q;
            q ^= px;
            x = next;
        }
        return {r, p};
    }
    // Joins a and b with flip(a) xor flip(b) = rel; false when that contradicts.
    bool unite(int a, int b, char rel) {
        auto [ra, pa] = find(a);
        auto [rb, pb] = find(b);
        if (ra == rb) return (pa ^ pb) == rel;
        if (ra > rb) std::swap(ra, rb);
        parent[rb] = ra;
        parity[rb] = static_cast<char>(pa ^ pb ^ rel);
        return true;
    }
};

void flip_triangle(TriangleMesh& m, size_t f) {
    std::swap(m.triangles[f][1], m.triangles[f][2]);
    if (f < m.corner_normals.size()) {
        auto& n = m.corner_normals[f];
        std::swap(n[1], n[2]);
        for (Vec3& v : n) v = -v;
    }
    if (f < m.corner_uvs.size()) std::swap(m.corner_uvs[f][1], m.corner_uvs[f][2]);
}

} // namespace

OrientationResult orient_surfaces(TriangleMesh& mesh) {
    OrientationResult out;
    const int ns = static_cast<int>(mesh.surface_names.size());
    if (ns < 1 || mesh.triangle_surface.size() != mesh.triangles.size()) return out;

    // Directed uses of every undirected edge.
    std::unordered_map<std::uint64_t, EdgeUse> edges;
    edges.reserve(2 * mesh.triangles.size());
    for (size_t f = 0; f < mesh.triangles.size(); ++f) {
        const int s = mesh.triangle_surface[f];
        for (int k = 0; k < 3; ++k) {
            const int a = mesh.triangles[f][k], b = mesh.triangles[f][(k + 1) % 3];
            if (a == b) continue;
            const auto key = (static_cast<std::uint64_t>(std::min(a, b)) << 32) |
                             static_cast<std::uint32_t>(std::max(a, b));
            EdgeUse& e = edges[key];
            if (e.count == 0) {
                e.surface = s;
                e.forward = a < b;
            } else if (e.count == 1 && s != e.surface) {
                e.other = s;
                e.other_forward = a < b;
            } else if (e.count >= 1) {
                e.mixed = e.mixed || e.count >= 2 || s != e.surface;
            }
            ++e.count;
        }
    }

    // Votes per surface pair: opposite directions keep both, equal directions
    // flip one. Majority decides; a pair with votes both ways is a conflict.
    std::unordered_map<std::uint64_t, std::array<int, 2>> votes;
    for (const auto& [key, e] : edges) {
        if (e.count != 2 || e.mixed || e.other < 0) continue;
        const int a = std::min(e.surface, e.other), b = std::max(e.surface, e.other);
        const auto pair = (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b);
        ++votes[pair][e.forward == e.other_forward ? 1 : 0];
    }
    std::vector<std::pair<std::uint64_t, std::array<int, 2>>> ordered(votes.begin(), votes.end());
    std::sort(ordered.begin(), ordered.end(),
              [](const auto& x, const auto& y) { return x.first < y.first; });
    ParitySets sets(ns);
    for (const auto& [pair, v] : ordered) {
        if (v[0] != 0 && v[1] != 0) ++out.conflicts;
        const char rel = v[1] > v[0] ? 1 : 0;
        if (!sets.unite(static_cast<int>(pair >> 32), static_cast<int>(pair & 0xffffffffu), rel))
            ++out.conflicts;
    }

    // Per component: keep the orientation of most triangles; a closed component
    // (every edge used twice) then faces outward.
    std::vector<int> triangles_of(ns, 0);
    for (int s : mesh.triangle_surface) ++triangles_of[s];
    std::vector<long long> keep(ns, 0); // per root: triangles keeping minus flipping
    std::vector<char> parity(ns);
    std::vector<int> root(ns);
    for (int s = 0; s < ns; ++s) {
        const auto [r, p] = sets.find(s);
        root[s] = r;
        parity[s] = p;
        keep[r] += p ? -triangles_of[s] : triangles_of[s];
    }
    std::vector<char> flip_root(ns, 0);
    for (int s = 0; s < ns; ++s)
        if (root[s] == s) flip_root[s] = keep[s] < 0;
    std::vector<char> open(ns, 0);
    for (const auto& [key, e] : edges)
        if (e.count != 2 || e.mixed) open[root[e.surface]] = 1;
    std::vector<double> volume(ns, 0);
    for (size_t f = 0; f < mesh.triangles.size(); ++f) {
        const int s = mesh.triangle_surface[f];
        const Vec3 &p = mesh.positions[mesh.triangles[f][0]],
                   &q = mesh.positions[mesh.triangles[f][1]],
                   &r = mesh.positions[mesh.triangles[f][2]];
        const double v = dot(p, cross(q, r));
        volume[root[s]] += (parity[s] ^ flip_root[root[s]]) ? -v : v;
    }
    for (int s = 0; s < ns; ++s)
        if (root[s] == s && !open[s] && volume[s] < 0) flip_root[s] ^= 1;

    std::vector<char> flip(ns);
    for (int s = 0; s < ns; ++s) {
        flip[s] = parity[s] ^ flip_root[root[s]];
        out.flipped_surfaces += flip[s];
    }
    for (size_t f = 0; f < mesh.triangles.size(); ++f)
        if (flip[mesh.triangle_surface[f]]) flip_triangle(mesh, f);
    return out;
}

} // namespace seamless
