// SPDX-License-Identifier: MIT
#include <seamless/base/check.h>
#include <seamless/base/disjoint_sets.h>
#include <seamless/mesh/check/edge_topology.h>

#include <algorithm>
#include <tuple>

namespace seamless {
namespace {

// Corner index 3 t + c of vertex v in triangle t; v is an end of one of t's
// edges (an edge use or a border join), so it is one of t's corners.
int corner(const std::vector<std::array<int, 3>>& T, int t, int v) {
    for (int c = 0; c < 3; ++c)
        if (T[t][c] == v) return 3 * t + c;
    SEAMLESS_CHECK(false, "an edge's end is a corner of the edge's triangle");
}

} // namespace

EdgeTopology edge_topology(const WeldedMesh& mesh) {
    const auto& P = mesh.positions;
    const auto& T = mesh.triangles;
    const int nf = static_cast<int>(T.size());
    EdgeTopology E;
    E.uses.reserve(3 * static_cast<size_t>(nf));
    for (int t = 0; t < nf; ++t)
        for (int c = 0; c < 3; ++c) {
            const int a = T[t][c], b = T[t][(c + 1) % 3];
            if (a != b) E.uses.push_back({std::min(a, b), std::max(a, b), t, a < b});
        }
    std::sort(E.uses.begin(), E.uses.end(), [](const EdgeUse& x, const EdgeUse& y) {
        return std::tie(x.lo, x.hi, x.triangle) < std::tie(y.lo, y.hi, y.triangle);
    });
    const auto& U = E.uses;
    for (size_t i = 0; i < U.size();) {
        size_t j = i;
        while (j < U.size() && U[j].lo == U[i].lo && U[j].hi == U[i].hi) ++j;
        const int k = static_cast<int>(j - i);
        E.groups.push_back({static_cast<int>(i), k});
        if (k == 1) E.border.push_back(U[i]);
        if (k >= 3) {
            E.non_manifold_edges.push_back({U[i].lo, U[i].hi, P[U[i].lo], P[U[i].hi], k});
            E.bad_triangles.push_back(U[i].triangle);
        }
        if (k == 2 && U[i].forward == U[i + 1].forward) {
            E.inconsistent_orientation.push_back(
                {U[i].triangle, U[i + 1].triangle, (P[U[i].lo] + P[U[i].hi]) / 2.0});
            E.bad_triangles.push_back(U[i].triangle);
        }
        i = j;
    }
    return E;
}

Shells find_shells(const WeldedMesh& mesh, const EdgeTopology& E,
                   const std::vector<BorderJoin>& joins) {
    const auto& P = mesh.positions;
    const auto& T = mesh.triangles;
    const int nf = static_cast<int>(T.size());
    // Shells and corner fans (corners of one vertex) are joined across the same
    // edges: every edge of two or more uses, and the border joins.
    DisjointSets shells(nf);
    DisjointSets fans(3 * static_cast<size_t>(nf));
    for (auto [first, k] : E.groups) {
        const EdgeUse& a = E.uses[first];
        for (int m = first + 1; m < first + k; ++m) {
            const EdgeUse& b = E.uses[m];
            shells.unite(a.triangle, b.triangle);
            fans.unite(corner(T, a.triangle, a.lo), corner(T, b.triangle, a.lo));
            fans.unite(corner(T, a.triangle, a.hi), corner(T, b.triangle, a.hi));
        }
    }
    for (const BorderJoin& j : joins) {
        shells.unite(j.t0, j.t1);
        fans.unite(corner(T, j.t0, j.vertex), corner(T, j.t1, j.vertex));
    }

    // Shells, numbered in the order of their first triangle.
    Shells S;
    S.triangle_shell.assign(nf, -1);
    int n = 0;
    for (int t = 0; t < nf; ++t) {
        const int r = shells.find(t);
        if (S.triangle_shell[r] < 0) S.triangle_shell[r] = n++;
        S.triangle_shell[t] = S.triangle_shell[r];
    }
    S.shells.resize(n);
    S.manifold_bad.assign(n, 0);
    for (int t = 0; t < nf; ++t) ++S.shells[S.triangle_shell[t]].triangles;
    for (auto [first, k] : E.groups) {
        ComponentReport& C = S.shells[S.triangle_shell[E.uses[first].triangle]];
        ++C.edges;
        C.border_edges += k == 1;
    }
    for (int t : E.bad_triangles) S.manifold_bad[S.triangle_shell[t]] = 1;
    for (auto& C : S.shells) C.closed = C.border_edges == 0;

    // Fans at each vertex, by shell. Two fans of one shell pinch it there (a
    // non-manifold vertex); fans of different shells make a shell contact.
    std::vector<std::array<int, 3>> vsf; // vertex, shell, fan root
    vsf.reserve(3 * static_cast<size_t>(nf));
    for (int t = 0; t < nf; ++t)
        for (int c = 0; c < 3; ++c) {
            const int v = T[t][c];
            if (c > 0 && (T[t][0] == v || (c == 2 && T[t][1] == v))) continue;
            vsf.push_back({v, S.triangle_shell[t], fans.find(3 * t + c)});
        }
    std::sort(vsf.begin(), vsf.end());
    vsf.erase(std::unique(vsf.begin(), vsf.end()), vsf.end());
    for (size_t i = 0; i < vsf.size();) {
        const int v = vsf[i][0];
        int nshells = 0;
        bool pinched = false;
        size_t j = i;
        for (; j < vsf.size() && vsf[j][0] == v; ++j)
            if (j == i || vsf[j][1] != vsf[j - 1][1]) {
                ++nshells;
                ++S.shells[vsf[j][1]].vertices;
            } else {
                pinched = true;
                S.manifold_bad[vsf[j][1]] = 1;
            }
        if (pinched) S.non_manifold_vertices.push_back({v, P[v]});
        if (nshells > 1) S.shell_contacts.push_back({v, P[v]});
        i = j;
    }
    return S;
}

} // namespace seamless
