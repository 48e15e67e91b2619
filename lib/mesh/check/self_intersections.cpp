// SPDX-License-Identifier: MIT
// Exact predicates (Epick) for degeneracy and triangle-triangle intersection,
// box_self_intersection_d for the candidate pairs.
#include <seamless/base/segment_distance.h>
#include <seamless/mesh/check/bits_hash.h>
#include <seamless/mesh/check/self_intersections.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

namespace seamless {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;

Point to_cgal(Vec3 p) {
    return {p.x, p.y, p.z};
}

Vec3 centroid(const std::vector<Vec3>& P, const std::array<int, 3>& t) {
    return (P[t[0]] + P[t[1]] + P[t[2]]) / 3.0;
}

bool collinear(const std::vector<Vec3>& P, const std::array<int, 3>& f) {
    return CGAL::collinear(to_cgal(P[f[0]]), to_cgal(P[f[1]]), to_cgal(P[f[2]]));
}

struct TripleHash {
    size_t operator()(const std::array<int, 3>& k) const {
        uint64_t h = 1469598103934665603ull;
        for (int x : k) h = (h ^ static_cast<uint32_t>(x)) * 1099511628211ull;
        return static_cast<size_t>(h ^ (h >> 31));
    }
};

// Whether two non-degenerate triangles intersect beyond the vertices they
// share (the adjacency rules of CGAL PMP::self_intersections).
bool triangles_intersect(const std::vector<Vec3>& P, std::array<int, 3> a, std::array<int, 3> b) {
    int shared = 0;
    for (int u : a)
        for (int v : b) shared += u == v;
    const K::Triangle_3 ta(to_cgal(P[a[0]]), to_cgal(P[a[1]]), to_cgal(P[a[2]]));
    const K::Triangle_3 tb(to_cgal(P[b[0]]), to_cgal(P[b[1]]), to_cgal(P[b[2]]));
    if (shared == 0) return CGAL::do_intersect(ta, tb);
    if (shared >= 3) return false; // a duplicate, reported as such
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
                                         const std::vector<const TJunction*>& tverts) {
    std::vector<std::array<int, 3>> parts{f};
    for (const TJunction* tj : tverts) {
        const int m = tj->vertex;
        const double tol = tj->tolerance;
        bool done = false;
        for (size_t i = 0; i < parts.size() && !done; ++i) {
            const auto p = parts[i];
            for (int c = 0; c < 3 && !done; ++c) {
                const int u = p[c], w = p[(c + 1) % 3], o = p[(c + 2) % 3];
                if (u == m || w == m || o == m) continue;
                if (point_segment_distance(P[m], P[u], P[w]) <= tol && distance(P[m], P[u]) > tol &&
                    distance(P[m], P[w]) > tol) {
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

std::vector<TriangleDefect> degenerate_triangles(const WeldedMesh& mesh) {
    const auto& P = mesh.positions;
    std::vector<TriangleDefect> out;
    for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
        const auto& f = mesh.triangles[t];
        if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2] || collinear(P, f))
            out.push_back({t, centroid(P, f)});
    }
    return out;
}

std::vector<TrianglePair> duplicated_triangles(const WeldedMesh& mesh) {
    std::unordered_map<std::array<int, 3>, int, TripleHash> first;
    first.reserve(mesh.triangles.size());
    std::vector<TrianglePair> out;
    for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
        auto key = mesh.triangles[t];
        std::sort(key.begin(), key.end());
        auto [it, inserted] = first.try_emplace(key, t);
        if (!inserted) out.push_back({it->second, t, centroid(mesh.positions, mesh.triangles[t])});
    }
    return out;
}

Intersections find_intersections(const WeldedMesh& mesh, const std::vector<int>& triangle_shell,
                                 const std::vector<TriangleDefect>& degenerate,
                                 const std::vector<TrianglePair>& duplicated,
                                 const std::vector<TJunction>& t_junctions) {
    const auto& P = mesh.positions;
    const auto& T = mesh.triangles;
    const int nf = static_cast<int>(T.size());
    std::vector<char> skip(nf, 0);
    for (const auto& d : degenerate) skip[d.triangle] = 1;
    for (const auto& d : duplicated) skip[d.t1] = 1;
    // Without welding, copies with their own vertices: bit-identical corner
    // positions. Only the first of a body takes part (with welding these are
    // the duplicates; a copy in another body is a contact).
    {
        std::unordered_set<std::array<uint64_t, 10>, BitsHash> seen;
        for (int t = 0; t < nf; ++t) {
            if (skip[t]) continue;
            std::array<std::array<uint64_t, 3>, 3> c;
            for (int k = 0; k < 3; ++k) std::memcpy(c[k].data(), &P[T[t][k]], 24);
            std::sort(c.begin(), c.end());
            std::array<uint64_t, 10> key;
            for (int k = 0; k < 9; ++k) key[k] = c[k / 3][k % 3];
            key[9] = mesh.triangle_body.empty() ? 0 : static_cast<uint64_t>(mesh.triangle_body[t]);
            if (!seen.insert(key).second) skip[t] = 1;
        }
    }
    std::unordered_map<int, std::vector<const TJunction*>> tverts; // triangle -> its T-junctions
    for (const auto& tj : t_junctions) tverts[tj.triangle].push_back(&tj);

    using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, int>;
    std::vector<Box> boxes;
    for (int t = 0; t < nf; ++t) {
        if (skip[t]) continue;
        const CGAL::Bbox_3 b =
            to_cgal(P[T[t][0]]).bbox() + to_cgal(P[T[t][1]]).bbox() + to_cgal(P[T[t][2]]).bbox();
        boxes.push_back(Box(b, t));
    }
    Intersections out;
    auto parts = [&](int t) {
        auto it = tverts.find(t);
        return it == tverts.end() ? std::vector{T[t]} : split_at(P, T[t], it->second);
    };
    CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& x, const Box& y) {
        int a = x.info(), b = y.info();
        if (a > b) std::swap(a, b);
        bool hit = false;
        for (const auto& pa : parts(a))
            for (const auto& pb : parts(b))
                if (!hit && !collinear(P, pa) && !collinear(P, pb))
                    hit = triangles_intersect(P, pa, pb);
        if (!hit) return;
        const TrianglePair pr{a, b, centroid(P, T[a])};
        if (!mesh.same_body(a, b))
            out.contacts.push_back(pr);
        else
            (triangle_shell[a] == triangle_shell[b] ? out.self_intersections : out.overlaps)
                .push_back(pr);
    });
    auto by_index = [](const TrianglePair& x, const TrianglePair& y) {
        return std::tie(x.t0, x.t1) < std::tie(y.t0, y.t1);
    };
    std::sort(out.self_intersections.begin(), out.self_intersections.end(), by_index);
    std::sort(out.overlaps.begin(), out.overlaps.end(), by_index);
    std::sort(out.contacts.begin(), out.contacts.end(), by_index);
    return out;
}

} // namespace seamless
