// SPDX-License-Identifier: MIT
// Watertightness check. The only CGAL-heavy file: exact predicates (Epick) for
// degeneracy and triangle-triangle intersection, box_intersection_d for the
// candidate pairs, Surface_mesh + PMP for volume and outward orientation of
// closed shells. Topology, borders, T-junctions and cracks are plain code.
#include <seamless/mesh/check.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <unordered_map>

namespace seamless {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;

Point to_cgal(Vec3 p) {
    return {p.x, p.y, p.z};
}

struct DisjointSets {
    std::vector<int> parent;
    explicit DisjointSets(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
    int find(int x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    }
    void unite(int a, int b) {
        a = find(a), b = find(b);
        if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
};

struct BitsHash {
    size_t operator()(const std::array<uint64_t, 3>& k) const {
        uint64_t h = 1469598103934665603ull;
        for (uint64_t x : k) h = (h ^ x) * 1099511628211ull ^ (x >> 29);
        return static_cast<size_t>(h);
    }
};

// Distance from p to the segment ab.
double segment_distance(Vec3 p, Vec3 a, Vec3 b) {
    const Vec3 d = b - a;
    const double l2 = dot(d, d);
    double t = l2 > 0 ? dot(p - a, d) / l2 : 0;
    t = std::clamp(t, 0.0, 1.0);
    return distance(p, a + t * d);
}

Vec3 centroid(const std::vector<Vec3>& P, const std::array<int, 3>& t) {
    return (P[t[0]] + P[t[1]] + P[t[2]]) / 3.0;
}

// An edge-triangle incidence; `forward` when the triangle runs lo -> hi.
struct EdgeUse {
    int lo, hi, triangle;
    bool forward;
};

// Uniform grid over border edges, each inserted in every cell its box
// (inflated by the gap) touches.
class EdgeGrid {
  public:
    EdgeGrid(Vec3 origin, double cell) : origin_(origin), cell_(cell) {}
    void insert(int id, Vec3 a, Vec3 b, double pad) {
        Box3 box;
        box.extend(a);
        box.extend(b);
        auto lo = key(box.lo - Vec3{pad, pad, pad}), hi = key(box.hi + Vec3{pad, pad, pad});
        for (int64_t i = lo[0]; i <= hi[0]; ++i)
            for (int64_t j = lo[1]; j <= hi[1]; ++j)
                for (int64_t k = lo[2]; k <= hi[2]; ++k) cells_[pack({i, j, k})].push_back(id);
    }
    const std::vector<int>* at(Vec3 p) const {
        auto it = cells_.find(pack(key(p)));
        return it == cells_.end() ? nullptr : &it->second;
    }

  private:
    std::array<int64_t, 3> key(Vec3 p) const {
        return {static_cast<int64_t>(std::floor((p.x - origin_.x) / cell_)),
                static_cast<int64_t>(std::floor((p.y - origin_.y) / cell_)),
                static_cast<int64_t>(std::floor((p.z - origin_.z) / cell_))};
    }
    static uint64_t pack(std::array<int64_t, 3> k) {
        return (static_cast<uint64_t>(k[0] & 0x1fffff) << 42) |
               (static_cast<uint64_t>(k[1] & 0x1fffff) << 21) |
               static_cast<uint64_t>(k[2] & 0x1fffff);
    }
    Vec3 origin_;
    double cell_;
    std::unordered_map<uint64_t, std::vector<int>> cells_;
};

// Whether two non-degenerate triangles sharing `shared` vertices intersect
// beyond what they share (the adjacency rules of CGAL PMP::self_intersections).
bool triangles_intersect(const std::vector<Vec3>& P, std::array<int, 3> a, std::array<int, 3> b) {
    int shared = 0;
    for (int u : a)
        for (int v : b) shared += u == v;
    const K::Triangle_3 ta(to_cgal(P[a[0]]), to_cgal(P[a[1]]), to_cgal(P[a[2]]));
    const K::Triangle_3 tb(to_cgal(P[b[0]]), to_cgal(P[b[1]]), to_cgal(P[b[2]]));
    if (shared == 0) return CGAL::do_intersect(ta, tb);
    if (shared >= 3) return false; // a duplicate, reported as such
    // Rotate so the shared vertices come first in a.
    auto in = [](int v, const std::array<int, 3>& t) {
        return v == t[0] || v == t[1] || v == t[2];
    };
    if (shared == 2) {
        int ra = -1, rb = -1, p = -1, q = -1;
        for (int v : a)
            if (!in(v, b))
                ra = v;
            else if (p < 0)
                p = v;
            else
                q = v;
        for (int v : b)
            if (!in(v, a)) rb = v;
        // A fold: the opposite vertices are coplanar with the shared edge and on one side.
        const Point P0 = to_cgal(P[p]), P1 = to_cgal(P[q]), R = to_cgal(P[ra]), S = to_cgal(P[rb]);
        return CGAL::coplanar(P0, P1, R, S) &&
               CGAL::coplanar_orientation(P0, P1, R, S) == CGAL::POSITIVE;
    }
    // One shared vertex: the opposite edge of either meets the other triangle.
    int s = -1;
    for (int v : a)
        if (in(v, b)) s = v;
    std::array<int, 2> ea{}, eb{};
    int na = 0, nb = 0;
    for (int v : a)
        if (v != s) ea[na++] = v;
    for (int v : b)
        if (v != s) eb[nb++] = v;
    return CGAL::do_intersect(K::Segment_3(to_cgal(P[ea[0]]), to_cgal(P[ea[1]])), tb) ||
           CGAL::do_intersect(K::Segment_3(to_cgal(P[eb[0]]), to_cgal(P[eb[1]])), ta);
}

// Triangle f cut at the T-junction vertices lying on its edges, so that a
// neighbour touching f only at such a vertex shares it as a true vertex. The
// parts keep f's orientation.
std::vector<std::array<int, 3>> split_at(const std::vector<Vec3>& P, std::array<int, 3> f,
                                         const std::vector<int>& tverts, double gap) {
    std::vector<std::array<int, 3>> parts{f};
    for (int m : tverts) {
        bool done = false;
        for (size_t i = 0; i < parts.size() && !done; ++i) {
            const auto p = parts[i];
            for (int c = 0; c < 3 && !done; ++c) {
                const int u = p[c], w = p[(c + 1) % 3], o = p[(c + 2) % 3];
                if (u == m || w == m || o == m) continue;
                if (segment_distance(P[m], P[u], P[w]) <= gap && distance(P[m], P[u]) > gap &&
                    distance(P[m], P[w]) > gap) {
                    parts[i] = {u, m, o};
                    parts.push_back({m, w, o});
                    done = true;
                }
            }
        }
    }
    return parts;
}

} // namespace

CheckReport check_mesh(const TriangleMesh& mesh, const CheckOptions& options) {
    CheckReport R;
    const int nv_in = mesh.vertex_count(), nf = mesh.triangle_count();
    R.input_vertices = nv_in;
    R.triangles = nf;
    R.welded = options.weld;

    // Welding: vertices with bit-identical positions become one (the first).
    std::vector<int> remap(nv_in);
    std::vector<Vec3> P;
    if (options.weld) {
        std::unordered_map<std::array<uint64_t, 3>, int, BitsHash> first;
        first.reserve(nv_in);
        for (int i = 0; i < nv_in; ++i) {
            std::array<uint64_t, 3> k;
            std::memcpy(k.data(), &mesh.positions[i], sizeof k);
            auto [it, inserted] = first.try_emplace(k, static_cast<int>(P.size()));
            if (inserted) P.push_back(mesh.positions[i]);
            remap[i] = it->second;
        }
    } else {
        std::iota(remap.begin(), remap.end(), 0);
        P = mesh.positions;
    }
    R.welded_vertices = nv_in - static_cast<int>(P.size());
    const int nv = static_cast<int>(P.size());
    std::vector<std::array<int, 3>> T(nf);
    for (int t = 0; t < nf; ++t)
        for (int c = 0; c < 3; ++c) T[t][c] = remap[mesh.triangles[t][c]];

    std::vector<char> used(nv, 0);
    for (auto& t : T)
        for (int v : t) used[v] = 1;
    R.unreferenced_vertices = static_cast<int>(std::count(used.begin(), used.end(), 0));
    R.vertices = nv - R.unreferenced_vertices;
    Box3 box;
    for (int v = 0; v < nv; ++v)
        if (used[v]) box.extend(P[v]);
    R.d_max = box.max_extent();
    R.gap = options.gap > 0 ? options.gap : 1e-6 * R.d_max;

    // Edges: triangle sides sorted by their vertex pair.
    std::vector<EdgeUse> uses;
    uses.reserve(3 * static_cast<size_t>(nf));
    for (int t = 0; t < nf; ++t)
        for (int c = 0; c < 3; ++c) {
            const int a = T[t][c], b = T[t][(c + 1) % 3];
            if (a != b) uses.push_back({std::min(a, b), std::max(a, b), t, a < b});
        }
    std::sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) {
        return std::tie(x.lo, x.hi, x.triangle) < std::tie(y.lo, y.hi, y.triangle);
    });

    // Edge groups: borders, non-manifold edges, orientation. Shells (triangles
    // connected through shared edges, manifold or not) and corner fans (corners
    // of one vertex) are joined across the same edges.
    auto corner = [&](int t, int v) {
        for (int c = 0; c < 3; ++c)
            if (T[t][c] == v) return 3 * t + c;
        assert(false);
        return 3 * t;
    };
    DisjointSets shells(nf);
    DisjointSets fans(3 * static_cast<size_t>(nf));
    std::vector<EdgeUse> border;             // directed as in its triangle via `forward`
    std::vector<std::pair<int, int>> groups; // first use and number of uses of each edge
    std::vector<int> bad_triangles;          // on non-manifold or misoriented edges
    for (size_t i = 0; i < uses.size();) {
        size_t j = i;
        while (j < uses.size() && uses[j].lo == uses[i].lo && uses[j].hi == uses[i].hi) ++j;
        const int k = static_cast<int>(j - i);
        groups.push_back({static_cast<int>(i), k});
        if (k == 1) {
            border.push_back(uses[i]);
        } else {
            for (size_t m = i + 1; m < j; ++m) {
                shells.unite(uses[i].triangle, uses[m].triangle);
                fans.unite(corner(uses[i].triangle, uses[i].lo),
                           corner(uses[m].triangle, uses[i].lo));
                fans.unite(corner(uses[i].triangle, uses[i].hi),
                           corner(uses[m].triangle, uses[i].hi));
            }
        }
        if (k >= 3) {
            R.non_manifold_edges.push_back(
                {uses[i].lo, uses[i].hi, P[uses[i].lo], P[uses[i].hi], k});
            bad_triangles.push_back(uses[i].triangle);
        }
        if (k == 2 && uses[i].forward == uses[i + 1].forward) {
            R.inconsistent_orientation.push_back(
                {uses[i].triangle, uses[i + 1].triangle, (P[uses[i].lo] + P[uses[i].hi]) / 2.0});
            bad_triangles.push_back(uses[i].triangle);
        }
        i = j;
    }
    R.edges = static_cast<int>(groups.size());
    R.border_edges = static_cast<int>(border.size());
    R.closed = border.empty();
    // T-junctions and cracks: border vertices and edges near border edges.
    if (!border.empty()) {
        const double gap = R.gap;
        double mean = 0;
        for (auto& b : border) mean += distance(P[b.lo], P[b.hi]);
        mean /= static_cast<double>(border.size());
        const double cell = std::max({mean, 4 * gap, 1e-300});
        EdgeGrid grid(box.lo, cell);
        for (int e = 0; e < static_cast<int>(border.size()); ++e)
            grid.insert(e, P[border[e].lo], P[border[e].hi], gap);
        auto shares = [](const EdgeUse& e, int v) { return e.lo == v || e.hi == v; };

        std::vector<char> border_vertex(nv, 0);
        for (auto& b : border) border_vertex[b.lo] = border_vertex[b.hi] = 1;
        for (int v = 0; v < nv; ++v) {
            if (!border_vertex[v]) continue;
            const auto* cands = grid.at(P[v]);
            if (!cands) continue;
            for (int e : *cands) {
                const EdgeUse& b = border[e];
                const auto& f = T[b.triangle];
                if (f[0] == v || f[1] == v || f[2] == v) continue;
                const double d = segment_distance(P[v], P[b.lo], P[b.hi]);
                if (d <= gap && distance(P[v], P[b.lo]) > gap && distance(P[v], P[b.hi]) > gap)
                    R.t_junctions.push_back({v, P[v], b.triangle, b.lo, b.hi, d});
            }
        }
        // Edge f lies along edge e: both ends of f within the gap of e, at least one
        // of them at an end of e (ends only in e's interior are T-junctions).
        auto along = [&](const EdgeUse& f, const EdgeUse& e, double& g) {
            const Vec3 a = P[e.lo], b = P[e.hi];
            const double d0 = segment_distance(P[f.lo], a, b), d1 = segment_distance(P[f.hi], a, b);
            if (d0 > gap || d1 > gap) return false;
            auto at_end = [&](int v) {
                return distance(P[v], a) <= gap || distance(P[v], b) <= gap;
            };
            if (!at_end(f.lo) && !at_end(f.hi)) return false;
            g = std::max(d0, d1);
            return true;
        };
        // Border edges sharing one vertex s and lying along each other (the two
        // sides of a T-junction or of a crack that closes at s) count as one edge:
        // they join their fans at s and their shells, so the defect reported is the
        // T-junction or crack, not a non-manifold vertex or a shell contact.
        auto overlapping = [&](const EdgeUse& f, const EdgeUse& e, int s) {
            const int fo = f.lo == s ? f.hi : f.lo, eo = e.lo == s ? e.hi : e.lo;
            return segment_distance(P[fo], P[e.lo], P[e.hi]) <= gap ||
                   segment_distance(P[eo], P[f.lo], P[f.hi]) <= gap;
        };
        for (int fi = 0; fi < static_cast<int>(border.size()); ++fi) {
            const EdgeUse& f = border[fi];
            for (int s : {f.lo, f.hi}) {
                const auto* cands = grid.at(P[s]);
                if (!cands) continue;
                for (int ei : *cands) {
                    const EdgeUse& e = border[ei];
                    if (ei == fi || !shares(e, s) || (shares(e, f.lo) && shares(e, f.hi))) continue;
                    if (overlapping(f, e, s)) {
                        fans.unite(corner(f.triangle, s), corner(e.triangle, s));
                        shells.unite(f.triangle, e.triangle);
                    }
                }
            }
        }
        for (int fi = 0; fi < static_cast<int>(border.size()); ++fi) {
            const EdgeUse& f = border[fi];
            int best = -1;
            double best_gap = -1;
            for (int v : {f.lo, f.hi}) {
                const auto* cands = grid.at(P[v]);
                if (!cands) continue;
                for (int ei : *cands) {
                    const EdgeUse& e = border[ei];
                    if (ei == fi || shares(e, f.lo) || shares(e, f.hi)) continue;
                    double g = 0;
                    if ((along(f, e, g) || along(e, f, g)) && g > best_gap) {
                        best = ei;
                        best_gap = g;
                    }
                }
            }
            if (best >= 0) {
                const EdgeUse& e = border[best];
                R.cracks.push_back({f.triangle, f.lo, f.hi, e.triangle, e.lo, e.hi,
                                    (P[f.lo] + P[f.hi]) / 2.0, best_gap});
                R.widest_crack = std::max(R.widest_crack, best_gap);
            }
        }
    }

    // Shells, numbered in the order of their first triangle.
    std::vector<int> comp_id(nf, -1);
    int ncomp = 0;
    for (int t = 0; t < nf; ++t) {
        const int r = shells.find(t);
        if (comp_id[r] < 0) comp_id[r] = ncomp++;
        comp_id[t] = comp_id[r];
    }
    R.triangle_component = comp_id;
    R.components.resize(ncomp);
    for (int t = 0; t < nf; ++t) ++R.components[comp_id[t]].triangles;
    for (auto [first, k] : groups) {
        ComponentReport& C = R.components[comp_id[uses[first].triangle]];
        ++C.edges;
        C.border_edges += k == 1;
    }
    std::vector<int> manifold_bad_comp(ncomp, 0);
    for (int t : bad_triangles) manifold_bad_comp[comp_id[t]] = 1;

    // Fans at each vertex, by shell. Two fans of one shell pinch it there (a
    // non-manifold vertex); fans of different shells make a shell contact. A
    // vertex counts once in each shell it belongs to.
    {
        std::vector<std::array<int, 3>> vsf; // vertex, shell, fan root
        vsf.reserve(3 * static_cast<size_t>(nf));
        for (int t = 0; t < nf; ++t)
            for (int c = 0; c < 3; ++c) {
                const int v = T[t][c];
                if (c > 0 && (T[t][0] == v || (c == 2 && T[t][1] == v))) continue;
                vsf.push_back({v, comp_id[t], fans.find(3 * t + c)});
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
                    ++R.components[vsf[j][1]].vertices;
                } else {
                    pinched = true;
                    manifold_bad_comp[vsf[j][1]] = 1;
                }
            if (pinched) R.non_manifold_vertices.push_back({v, P[v]});
            if (nshells > 1) R.shell_contacts.push_back({v, P[v]});
            i = j;
        }
    }

    // Degenerate (zero-area, exactly) and duplicated triangles.
    std::vector<char> degenerate(nf, 0);
    for (int t = 0; t < nf; ++t) {
        const auto& f = T[t];
        if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2] ||
            CGAL::collinear(to_cgal(P[f[0]]), to_cgal(P[f[1]]), to_cgal(P[f[2]]))) {
            degenerate[t] = 1;
            R.degenerate_triangles.push_back({t, centroid(P, f)});
        }
    }
    {
        std::vector<std::pair<std::array<int, 3>, int>> sorted(nf);
        for (int t = 0; t < nf; ++t) {
            auto f = T[t];
            std::sort(f.begin(), f.end());
            sorted[t] = {f, t};
        }
        std::sort(sorted.begin(), sorted.end());
        for (int i = 1; i < nf; ++i) {
            int first = i - 1;
            while (first > 0 && sorted[first - 1].first == sorted[i].first) --first;
            if (sorted[i].first == sorted[i - 1].first)
                R.duplicated_triangles.push_back(
                    {sorted[first].second, sorted[i].second, centroid(P, T[sorted[i].second])});
        }
    }

    // Border loops: walk border edges through their shared vertices.
    {
        std::unordered_map<int, std::vector<int>> at;
        for (int e = 0; e < static_cast<int>(border.size()); ++e) {
            at[border[e].lo].push_back(e);
            at[border[e].hi].push_back(e);
        }
        std::vector<char> done(border.size(), 0);
        for (int e0 = 0; e0 < static_cast<int>(border.size()); ++e0) {
            if (done[e0]) continue;
            BorderLoop loop;
            const int start = border[e0].forward ? border[e0].lo : border[e0].hi;
            loop.start = P[start];
            int e = e0, v = start;
            for (;;) {
                done[e] = 1;
                ++loop.edges;
                loop.length += distance(P[border[e].lo], P[border[e].hi]);
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
            R.border_loops.push_back(loop);
        }
    }

    // Self-intersections (same shell) and overlaps (different shells).
    {
        using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, int>;
        std::unordered_map<int, std::vector<int>> tverts; // triangle -> T-junction vertices
        for (const auto& tj : R.t_junctions) tverts[tj.triangle].push_back(tj.vertex);
        auto collinear = [&](const std::array<int, 3>& f) {
            return CGAL::collinear(to_cgal(P[f[0]]), to_cgal(P[f[1]]), to_cgal(P[f[2]]));
        };
        std::vector<Box> boxes;
        for (int t = 0; t < nf; ++t) {
            if (degenerate[t]) continue;
            CGAL::Bbox_3 b = to_cgal(P[T[t][0]]).bbox() + to_cgal(P[T[t][1]]).bbox() +
                             to_cgal(P[T[t][2]]).bbox();
            boxes.push_back(Box(b, t));
        }
        CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& x, const Box& y) {
            int a = x.info(), b = y.info();
            if (a > b) std::swap(a, b);
            auto parts = [&](int t) {
                auto it = tverts.find(t);
                return it == tverts.end() ? std::vector{T[t]}
                                          : split_at(P, T[t], it->second, R.gap);
            };
            bool hit = false;
            for (const auto& x : parts(a))
                for (const auto& y : parts(b))
                    if (!hit && !collinear(x) && !collinear(y)) hit = triangles_intersect(P, x, y);
            if (!hit) return;
            TrianglePair pr{a, b, centroid(P, T[a])};
            (comp_id[a] == comp_id[b] ? R.self_intersections : R.overlaps).push_back(pr);
        });
        auto by_index = [](const TrianglePair& x, const TrianglePair& y) {
            return std::tie(x.t0, x.t1) < std::tie(y.t0, y.t1);
        };
        std::sort(R.self_intersections.begin(), R.self_intersections.end(), by_index);
        std::sort(R.overlaps.begin(), R.overlaps.end(), by_index);
    }

    // Closed shells: Euler characteristic, genus; volume and outward
    // orientation through CGAL when the shell is a valid closed surface.
    std::vector<std::vector<int>> comp_tris(ncomp);
    for (int t = 0; t < nf; ++t) comp_tris[comp_id[t]].push_back(t);
    for (int c = 0; c < ncomp; ++c) {
        ComponentReport& C = R.components[c];
        C.closed = C.border_edges == 0;
        if (!C.closed) continue;
        C.euler = C.vertices - C.edges + C.triangles;
        if (manifold_bad_comp[c]) continue;
        if (*C.euler % 2 == 0) C.genus = (2 - *C.euler) / 2;
        CGAL::Surface_mesh<Point> sm;
        std::unordered_map<int, CGAL::Surface_mesh<Point>::Vertex_index> vid;
        bool ok = true;
        for (int t : comp_tris[c]) {
            std::array<CGAL::Surface_mesh<Point>::Vertex_index, 3> vs;
            for (int k = 0; k < 3; ++k) {
                auto [it, inserted] = vid.try_emplace(T[t][k]);
                if (inserted) it->second = sm.add_vertex(to_cgal(P[T[t][k]]));
                vs[k] = it->second;
            }
            if (sm.add_face(vs[0], vs[1], vs[2]) == CGAL::Surface_mesh<Point>::null_face()) {
                ok = false;
                break;
            }
        }
        if (!ok || !CGAL::is_closed(sm)) continue;
        C.volume = CGAL::Polygon_mesh_processing::volume(sm);
        C.outward = CGAL::Polygon_mesh_processing::is_outward_oriented(sm);
    }
    return R;
}

int defect_count(const CheckReport& r) {
    return static_cast<int>(r.cracks.size() + r.t_junctions.size() + r.non_manifold_edges.size() +
                            r.non_manifold_vertices.size() + r.degenerate_triangles.size() +
                            r.duplicated_triangles.size() + r.inconsistent_orientation.size() +
                            r.self_intersections.size());
}

bool check_passed(const CheckReport& r, const CheckOptions& options) {
    if (defect_count(r) > 0) return false;
    if (options.require_closed)
        for (const auto& c : r.components)
            if (!c.closed) return false;
    return true;
}

std::string to_json(const CheckReport& r, int max_listed) {
    using nlohmann::json;
    auto pt = [](Vec3 p) { return json::array({p.x, p.y, p.z}); };
    auto list = [&](const auto& v, auto&& one) {
        json a = json::array();
        for (size_t i = 0; i < v.size() && static_cast<int>(i) < max_listed; ++i)
            a.push_back(one(v[i]));
        return json{{"count", v.size()}, {"listed", a}};
    };
    auto pair = [&](const TrianglePair& p) {
        return json{{"triangles", {p.t0, p.t1}}, {"location", pt(p.location)}};
    };
    json j;
    j["d_max"] = r.d_max;
    j["gap"] = r.gap;
    j["weld"] = r.welded;
    j["input_vertices"] = r.input_vertices;
    j["welded_vertices"] = r.welded_vertices;
    j["unreferenced_vertices"] = r.unreferenced_vertices;
    j["vertices"] = r.vertices;
    j["triangles"] = r.triangles;
    j["edges"] = r.edges;
    j["components"] = r.components.size();
    j["border_edges"] = r.border_edges;
    j["closed"] = r.closed;
    j["border_loops"] = list(r.border_loops, [&](const BorderLoop& l) {
        return json{
            {"edges", l.edges}, {"length", l.length}, {"start", pt(l.start)}, {"closed", l.closed}};
    });
    j["non_manifold_edges"] = list(r.non_manifold_edges, [&](const EdgeDefect& e) {
        return json{{"vertices", {e.v0, e.v1}},
                    {"from", pt(e.p0)},
                    {"to", pt(e.p1)},
                    {"triangles", e.triangles}};
    });
    auto vertex = [&](const VertexDefect& v) {
        return json{{"vertex", v.vertex}, {"location", pt(v.position)}};
    };
    j["non_manifold_vertices"] = list(r.non_manifold_vertices, vertex);
    j["shell_contacts"] = list(r.shell_contacts, vertex);
    j["t_junctions"] = list(r.t_junctions, [&](const TJunction& t) {
        return json{{"vertex", t.vertex},
                    {"location", pt(t.position)},
                    {"triangle", t.triangle},
                    {"edge", {t.v0, t.v1}},
                    {"distance", t.distance}};
    });
    j["cracks"] = list(r.cracks, [&](const Crack& c) {
        return json{{"triangle", c.triangle},
                    {"edge", {c.v0, c.v1}},
                    {"other_triangle", c.other_triangle},
                    {"other_edge", {c.w0, c.w1}},
                    {"location", pt(c.location)},
                    {"gap", c.gap}};
    });
    j["widest_crack"] = r.widest_crack;
    j["degenerate_triangles"] = list(r.degenerate_triangles, [&](const TriangleDefect& d) {
        return json{{"triangle", d.triangle}, {"location", pt(d.location)}};
    });
    j["duplicated_triangles"] = list(r.duplicated_triangles, pair);
    j["inconsistent_orientation"] = list(r.inconsistent_orientation, pair);
    j["self_intersections"] = list(r.self_intersections, pair);
    j["overlaps"] = list(r.overlaps, pair);
    json comps = json::array();
    for (const auto& c : r.components) {
        json o{{"vertices", c.vertices},
               {"triangles", c.triangles},
               {"edges", c.edges},
               {"border_edges", c.border_edges},
               {"closed", c.closed}};
        if (c.euler) o["euler"] = *c.euler;
        if (c.genus) o["genus"] = *c.genus;
        if (c.volume) o["volume"] = *c.volume;
        if (c.outward) o["outward"] = *c.outward;
        comps.push_back(o);
    }
    j["component_list"] = comps;
    j["defects"] = defect_count(r);
    return j.dump(2);
}

} // namespace seamless
