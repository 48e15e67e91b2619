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

// The border defects of one mesh, found in the steps of docs/check.md (3, 5
// and 6) in order; each step reads what the steps before it left in the
// members.
class BorderDefectFinder {
  public:
    BorderDefectFinder(const WeldedMesh& mesh, const std::vector<EdgeUse>& border,
                       GapTolerance tolerance)
        : M(mesh), P(mesh.positions), T(mesh.triangles), border_(border), tolerance_(tolerance),
          nb_(static_cast<int>(border.size())) {}

    BorderDefects find() && {
        if (nb_ == 0) return std::move(D);
        index_border_edges();
        find_first_copies();
        find_candidate_pairs();
        crack_gap_.assign(nb_, -1);
        crack_other_.assign(nb_, -1);
        find_t_junctions();
        find_edges_along();
        group_seams();
        walk_border_loops();
        return std::move(D);
    }

  private:
    // Border edges at each vertex; lengths.
    void index_border_edges() {
        len_.resize(nb_);
        at_.resize(P.size());
        for (int e = 0; e < nb_; ++e) {
            const EdgeUse& b = border_[e];
            len_[e] = distance(P[b.lo], P[b.hi]);
            for (int v : {b.lo, b.hi}) at_[v].push_back(e);
        }
    }

    // Border edges of one body with bit-identical end positions (only without
    // welding: after it, positions are vertices) are judged once, by the first
    // of them; the others are cracks along it. k copies of a triangle cost
    // O(k), not O(k^2).
    void find_first_copies() {
        first_copy_.resize(nb_);
        std::unordered_map<std::array<uint64_t, 7>, int, BitsHash> first;
        for (int e = 0; e < nb_; ++e) {
            std::array<uint64_t, 7> key;
            Vec3 a = P[border_[e].lo], b = P[border_[e].hi];
            std::memcpy(key.data(), &a, 24);
            std::memcpy(key.data() + 3, &b, 24);
            if (std::lexicographical_compare(key.begin() + 3, key.end(), key.begin(),
                                             key.begin() + 3))
                std::swap_ranges(key.begin(), key.begin() + 3, key.begin() + 3);
            key[6] = M.triangle_body.empty()
                         ? 0
                         : static_cast<uint64_t>(M.triangle_body[border_[e].triangle]);
            first_copy_[e] = first.try_emplace(key, e).first->second;
        }
    }

    // Candidate pairs: border edges whose boxes, each grown by its own
    // tolerance, overlap: a pair's tolerance is that of its longer edge.
    void find_candidate_pairs() {
        using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, int>;
        std::vector<Box> boxes;
        boxes.reserve(nb_);
        for (int e = 0; e < nb_; ++e) {
            if (first_copy_[e] != e) continue;
            const Vec3 a = P[border_[e].lo], b = P[border_[e].hi];
            const double pad = tolerance_.at(len_[e]);
            boxes.emplace_back(CGAL::Bbox_3(std::min(a.x, b.x) - pad, std::min(a.y, b.y) - pad,
                                            std::min(a.z, b.z) - pad, std::max(a.x, b.x) + pad,
                                            std::max(a.y, b.y) + pad, std::max(a.z, b.z) + pad),
                               e);
        }
        // Two sides of one triangle are its shape, not a crack (a zero-area triangle
        // is reported as degenerate); borders of two bodies are judged apart.
        CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& x, const Box& y) {
            const int s = border_[x.info()].triangle, t = border_[y.info()].triangle;
            if (s != t && M.same_body(s, t)) pairs_.push_back(std::minmax(x.info(), y.info()));
        });
        std::sort(pairs_.begin(), pairs_.end());
    }

    // Per border edge: the widest crack found on it and the edge it was found against.
    void mark(int e, int other, double gap) {
        if (gap > crack_gap_[e]) crack_gap_[e] = gap, crack_other_[e] = other;
    }
    static bool shares(const EdgeUse& e, int v) { return e.lo == v || e.hi == v; }

    // T-junctions: a border vertex inside a border edge of a triangle it is not on.
    void find_t_junctions() {
        std::vector<std::pair<int, int>> vertex_edge; // (vertex, edge)
        for (auto [i, j] : pairs_)
            for (auto [f, e] : {std::pair{i, j}, std::pair{j, i}})
                for (int v : {border_[f].lo, border_[f].hi}) {
                    const auto& t = T[border_[e].triangle];
                    if (t[0] != v && t[1] != v && t[2] != v) vertex_edge.push_back({v, e});
                }
        std::sort(vertex_edge.begin(), vertex_edge.end());
        vertex_edge.erase(std::unique(vertex_edge.begin(), vertex_edge.end()), vertex_edge.end());
        for (auto [v, e] : vertex_edge) {
            const EdgeUse& b = border_[e];
            const double tol = tolerance_.at(len_[e]);
            const double d = point_segment_distance(P[v], P[b.lo], P[b.hi]);
            if (d <= tol && distance(P[v], P[b.lo]) > tol && distance(P[v], P[b.hi]) > tol) {
                D.t_junctions.push_back({v, P[v], b.triangle, b.lo, b.hi, d, tol});
                junction_edge_.push_back(e);
                mark(e, at_[v].front(), d);
            }
        }
    }

    // Border edges running along each other; those sharing a vertex join shells.
    void find_edges_along() {
        for (int e = 0; e < nb_; ++e) {
            const int f = first_copy_[e];
            if (f == e || border_[f].triangle == border_[e].triangle || !(len_[e] > 0)) continue;
            along_.push_back({f, e});
            mark(e, f, 0);
            mark(f, e, 0);
            for (int s : {border_[e].lo, border_[e].hi})
                if (shares(border_[f], s))
                    D.joins.push_back({border_[f].triangle, border_[e].triangle, s});
        }
        for (auto [i, j] : pairs_) {
            const int f = len_[i] <= len_[j] ? i : j, e = f == i ? j : i;
            const EdgeUse &bf = border_[f], &be = border_[e];
            double gap = 0;
            if (!runs_along(P[bf.lo], P[bf.hi], P[be.lo], P[be.hi], tolerance_.at(len_[e]), gap))
                continue;
            along_.push_back({i, j});
            mark(i, j, gap);
            mark(j, i, gap);
            for (int s : {bf.lo, bf.hi})
                if (shares(be, s)) D.joins.push_back({bf.triangle, be.triangle, s});
        }
    }

    // Seams: crack edges joined where they run along each other, share a vertex,
    // or meet at a T-junction; the cracks listed with their seam.
    void group_seams() {
        DisjointSets runs(nb_);
        for (auto [i, j] : along_) runs.unite(i, j);
        for (size_t k = 0; k < D.t_junctions.size(); ++k)
            for (int f : at_[D.t_junctions[k].vertex])
                if (crack_gap_[f] >= 0) runs.unite(f, junction_edge_[k]);
        for (size_t v = 0; v < at_.size(); ++v) {
            int first = -1;
            for (int e : at_[v])
                if (crack_gap_[e] >= 0) {
                    if (first < 0)
                        first = e;
                    else
                        runs.unite(first, e);
                }
        }
        std::vector<int> seam_of(nb_, -1);
        std::vector<std::vector<int>> seam_edges;
        for (int e = 0; e < nb_; ++e) {
            if (crack_gap_[e] < 0) continue;
            const int r = runs.find(e);
            if (seam_of[r] < 0) {
                seam_of[r] = static_cast<int>(seam_edges.size());
                seam_edges.emplace_back();
            }
            seam_of[e] = seam_of[r];
            seam_edges[seam_of[e]].push_back(e);
            const EdgeUse &b = border_[e], &o = border_[crack_other_[e]];
            D.cracks.push_back({b.triangle, b.lo, b.hi, o.triangle, o.lo, o.hi,
                                (P[b.lo] + P[b.hi]) / 2.0, crack_gap_[e], seam_of[e]});
            D.widest_crack = std::max(D.widest_crack, crack_gap_[e]);
        }
        for (const auto& edges : seam_edges) D.seams.push_back(seam(edges));
    }

    // A seam's extent: its length and widest gap, the crack edge midpoint
    // nearest the mean of the midpoints, and its two ends.
    Seam seam(const std::vector<int>& edges) const {
        Seam s;
        s.edges = static_cast<int>(edges.size());
        Vec3 mean{};
        for (int e : edges) {
            s.length += len_[e] / 2;
            s.gap = std::max(s.gap, crack_gap_[e]);
            mean += (P[border_[e].lo] + P[border_[e].hi]) / (2.0 * edges.size());
        }
        double nearest = std::numeric_limits<double>::infinity();
        auto farthest = [&](Vec3 from) {
            Vec3 best = from;
            double d = -1;
            for (int e : edges)
                for (int v : {border_[e].lo, border_[e].hi})
                    if (distance(P[v], from) > d) d = distance(P[v], from), best = P[v];
            return best;
        };
        for (int e : edges) {
            const Vec3 mid = (P[border_[e].lo] + P[border_[e].hi]) / 2.0;
            if (distance(mid, mean) < nearest) nearest = distance(mid, mean), s.location = mid;
        }
        s.from = farthest(mean);
        s.to = farthest(s.from);
        return s;
    }

    // Border loops: walk border edges through their shared vertices.
    void walk_border_loops() {
        std::vector<char> done(nb_, 0);
        for (int e0 = 0; e0 < nb_; ++e0) {
            if (done[e0]) continue;
            BorderLoop loop;
            const int start = border_[e0].forward ? border_[e0].lo : border_[e0].hi;
            loop.start = P[start];
            int e = e0, v = start;
            for (;;) {
                done[e] = 1;
                ++loop.edges;
                loop.triangles.push_back(border_[e].triangle);
                loop.length += len_[e];
                v = border_[e].lo == v ? border_[e].hi : border_[e].lo;
                if (v == start) break;
                int next = -1;
                for (int f : at_[v])
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
    }

    const WeldedMesh& M;
    const std::vector<Vec3>& P;
    const std::vector<std::array<int, 3>>& T;
    const std::vector<EdgeUse>& border_;
    const GapTolerance tolerance_;
    const int nb_;
    BorderDefects D;
    std::vector<double> len_;                // per border edge
    std::vector<std::vector<int>> at_;       // per vertex: its border edges
    std::vector<int> first_copy_;            // per border edge: the first with its end positions
    std::vector<std::pair<int, int>> pairs_; // candidate pairs (i < j), sorted
    std::vector<double> crack_gap_;          // per border edge: widest crack gap, -1 for none
    std::vector<int> crack_other_;           // per border edge: the edge of that crack
    std::vector<int> junction_edge_;         // per T-junction: its edge
    std::vector<std::pair<int, int>> along_; // border edge pairs running along each other
};

} // namespace

BorderDefects border_defects(const WeldedMesh& mesh, const std::vector<EdgeUse>& border,
                             GapTolerance tolerance) {
    return BorderDefectFinder(mesh, border, tolerance).find();
}

} // namespace seamless
