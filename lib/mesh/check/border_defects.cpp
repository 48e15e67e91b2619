// SPDX-License-Identifier: MIT
#include <seamless/base/disjoint_sets.h>
#include <seamless/base/segment_distance.h>
#include <seamless/mesh/check/bits_hash.h>
#include <seamless/mesh/check/border_defects.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/box_intersection_d.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <unordered_map>

namespace seamless {
namespace {

// Whether segment ab runs along segment cd: the part of ab whose projection
// falls inside cd is longer than tol and within tol of cd all along (the
// distance to cd's line is convex along ab, so its two ends decide). `gap`: the
// larger of the two end distances.
bool runs_along(Vec3 a, Vec3 b, Vec3 c, Vec3 d, double tol, double& gap) {
    const Vec3 u = d - c;
    const double l2 = dot(u, u);
    if (!(l2 > 0)) return false;
    const double sa = dot(a - c, u) / l2, sb = dot(b - c, u) / l2;
    const double lo = std::max(0.0, std::min(sa, sb)), hi = std::min(1.0, std::max(sa, sb));
    if (!((hi - lo) * std::sqrt(l2) > tol) || sa == sb) return false;
    auto on_ab = [&](double s) { return a + ((s - sa) / (sb - sa)) * (b - a); };
    const double g0 = distance(on_ab(lo), c + lo * u), g1 = distance(on_ab(hi), c + hi * u);
    gap = std::max(g0, g1);
    return gap <= tol;
}

} // namespace

BorderDefects border_defects(const WeldedMesh& mesh, const std::vector<EdgeUse>& border,
                             GapTolerance tolerance) {
    const auto& P = mesh.positions;
    const auto& T = mesh.triangles;
    const int nb = static_cast<int>(border.size());
    BorderDefects D;
    if (nb == 0) return D;

    // Border edges at each vertex; lengths.
    std::vector<double> len(nb);
    std::vector<std::vector<int>> at(P.size());
    for (int e = 0; e < nb; ++e) {
        const EdgeUse& b = border[e];
        len[e] = distance(P[b.lo], P[b.hi]);
        for (int v : {b.lo, b.hi}) at[v].push_back(e);
    }

    // Border edges with bit-identical end positions (only without welding: after
    // it, positions are vertices) are judged once, by the first of them; the
    // others are cracks along it. k copies of a triangle cost O(k), not O(k^2).
    std::vector<int> first_copy(nb);
    {
        std::unordered_map<std::array<uint64_t, 6>, int, BitsHash> first;
        for (int e = 0; e < nb; ++e) {
            std::array<uint64_t, 6> key;
            Vec3 a = P[border[e].lo], b = P[border[e].hi];
            std::memcpy(key.data(), &a, 24);
            std::memcpy(key.data() + 3, &b, 24);
            if (std::lexicographical_compare(key.begin() + 3, key.end(), key.begin(),
                                             key.begin() + 3))
                std::swap_ranges(key.begin(), key.begin() + 3, key.begin() + 3);
            first_copy[e] = first.try_emplace(key, e).first->second;
        }
    }

    // Candidate pairs: border edges whose boxes, each grown by its own
    // tolerance, overlap: a pair's tolerance is that of its longer edge.
    using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, int>;
    std::vector<Box> boxes;
    boxes.reserve(nb);
    for (int e = 0; e < nb; ++e) {
        if (first_copy[e] != e) continue;
        const Vec3 a = P[border[e].lo], b = P[border[e].hi];
        const double pad = tolerance.at(len[e]);
        boxes.emplace_back(CGAL::Bbox_3(std::min(a.x, b.x) - pad, std::min(a.y, b.y) - pad,
                                        std::min(a.z, b.z) - pad, std::max(a.x, b.x) + pad,
                                        std::max(a.y, b.y) + pad, std::max(a.z, b.z) + pad),
                           e);
    }
    // Two sides of one triangle are its shape, not a crack (a zero-area triangle
    // is reported as degenerate).
    std::vector<std::pair<int, int>> pairs;
    CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& x, const Box& y) {
        if (border[x.info()].triangle != border[y.info()].triangle)
            pairs.push_back(std::minmax(x.info(), y.info()));
    });
    std::sort(pairs.begin(), pairs.end());

    // Per border edge: the widest crack found on it and the edge it was found against.
    std::vector<double> crack_gap(nb, -1);
    std::vector<int> crack_other(nb, -1);
    auto mark = [&](int e, int other, double gap) {
        if (gap > crack_gap[e]) crack_gap[e] = gap, crack_other[e] = other;
    };
    auto shares = [](const EdgeUse& e, int v) { return e.lo == v || e.hi == v; };

    // T-junctions: a border vertex inside a border edge of a triangle it is not on.
    std::vector<std::pair<int, int>> vertex_edge; // (vertex, edge)
    for (auto [i, j] : pairs)
        for (auto [f, e] : {std::pair{i, j}, std::pair{j, i}})
            for (int v : {border[f].lo, border[f].hi}) {
                const auto& t = T[border[e].triangle];
                if (t[0] != v && t[1] != v && t[2] != v) vertex_edge.push_back({v, e});
            }
    std::sort(vertex_edge.begin(), vertex_edge.end());
    vertex_edge.erase(std::unique(vertex_edge.begin(), vertex_edge.end()), vertex_edge.end());
    std::vector<int> junction_edge; // per T-junction: its edge
    for (auto [v, e] : vertex_edge) {
        const EdgeUse& b = border[e];
        const double tol = tolerance.at(len[e]);
        const double d = point_segment_distance(P[v], P[b.lo], P[b.hi]);
        if (d <= tol && distance(P[v], P[b.lo]) > tol && distance(P[v], P[b.hi]) > tol) {
            D.t_junctions.push_back({v, P[v], b.triangle, b.lo, b.hi, d, tol});
            junction_edge.push_back(e);
            mark(e, at[v].front(), d);
        }
    }

    // Border edges running along each other; those sharing a vertex join shells.
    std::vector<std::pair<int, int>> along;
    for (int e = 0; e < nb; ++e) {
        const int f = first_copy[e];
        if (f == e || border[f].triangle == border[e].triangle || !(len[e] > 0)) continue;
        along.push_back({f, e});
        mark(e, f, 0);
        mark(f, e, 0);
        for (int s : {border[e].lo, border[e].hi})
            if (shares(border[f], s))
                D.joins.push_back({border[f].triangle, border[e].triangle, s});
    }
    for (auto [i, j] : pairs) {
        const int f = len[i] <= len[j] ? i : j, e = f == i ? j : i;
        const EdgeUse &bf = border[f], &be = border[e];
        double gap = 0;
        if (!runs_along(P[bf.lo], P[bf.hi], P[be.lo], P[be.hi], tolerance.at(len[e]), gap))
            continue;
        along.push_back({i, j});
        mark(i, j, gap);
        mark(j, i, gap);
        for (int s : {bf.lo, bf.hi})
            if (shares(be, s)) D.joins.push_back({bf.triangle, be.triangle, s});
    }

    // Seams: crack edges joined where they run along each other, share a vertex,
    // or meet at a T-junction.
    DisjointSets runs(nb);
    for (auto [i, j] : along) runs.unite(i, j);
    for (size_t k = 0; k < D.t_junctions.size(); ++k)
        for (int f : at[D.t_junctions[k].vertex])
            if (crack_gap[f] >= 0) runs.unite(f, junction_edge[k]);
    for (size_t v = 0; v < at.size(); ++v) {
        int first = -1;
        for (int e : at[v])
            if (crack_gap[e] >= 0) {
                if (first < 0)
                    first = e;
                else
                    runs.unite(first, e);
            }
    }
    std::vector<int> seam_of(nb, -1);
    std::vector<std::vector<int>> seam_edges;
    for (int e = 0; e < nb; ++e) {
        if (crack_gap[e] < 0) continue;
        const int r = runs.find(e);
        if (seam_of[r] < 0) {
            seam_of[r] = static_cast<int>(seam_edges.size());
            seam_edges.emplace_back();
        }
        seam_of[e] = seam_of[r];
        seam_edges[seam_of[e]].push_back(e);
        const EdgeUse &b = border[e], &o = border[crack_other[e]];
        D.cracks.push_back({b.triangle, b.lo, b.hi, o.triangle, o.lo, o.hi,
                            (P[b.lo] + P[b.hi]) / 2.0, crack_gap[e], seam_of[e]});
        D.widest_crack = std::max(D.widest_crack, crack_gap[e]);
    }
    for (const auto& edges : seam_edges) {
        Seam s;
        s.edges = static_cast<int>(edges.size());
        Vec3 mean{};
        for (int e : edges) {
            s.length += len[e] / 2;
            s.gap = std::max(s.gap, crack_gap[e]);
            mean += (P[border[e].lo] + P[border[e].hi]) / (2.0 * edges.size());
        }
        double nearest = std::numeric_limits<double>::infinity();
        auto farthest = [&](Vec3 from) {
            Vec3 best = from;
            double d = -1;
            for (int e : edges)
                for (int v : {border[e].lo, border[e].hi})
                    if (distance(P[v], from) > d) d = distance(P[v], from), best = P[v];
            return best;
        };
        for (int e : edges) {
            const Vec3 mid = (P[border[e].lo] + P[border[e].hi]) / 2.0;
            if (distance(mid, mean) < nearest) nearest = distance(mid, mean), s.location = mid;
        }
        s.from = farthest(mean);
        s.to = farthest(s.from);
        D.seams.push_back(s);
    }

    // Border loops: walk border edges through their shared vertices.
    std::vector<char> done(nb, 0);
    for (int e0 = 0; e0 < nb; ++e0) {
        if (done[e0]) continue;
        BorderLoop loop;
        const int start = border[e0].forward ? border[e0].lo : border[e0].hi;
        loop.start = P[start];
        int e = e0, v = start;
        for (;;) {
            done[e] = 1;
            ++loop.edges;
            loop.length += len[e];
            v = border[e].lo == v ? border[e].hi : border[e].lo;
            if (v == start) break;
            int next = -1;
            for (int f : at[v])
                if (!done[f]) {
                    next = f;
                    break;
                }
            if (next < 0) {
                loop.closed = false;
                break;
            }
            e = next;
        }
        D.loops.push_back(loop);
    }
    return D;
}

} // namespace seamless
