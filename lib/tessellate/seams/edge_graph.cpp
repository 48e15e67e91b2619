// SPDX-License-Identifier: MIT
#include <seamless/base/disjoint_sets.h>
#include <seamless/tessellate/seams/edge_graph.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <unordered_set>

namespace seamless {
namespace {

// An unpaired boundary line: its reference patch edge as a Bezier curve and
// its vertices (the subpatch side ends on it).
struct Line {
    int id = -1; // global edge
    int n = 1;   // degree
    std::array<HPoint, BezierPatch::kMaxOrder> cp{};
    Box3 box;              // control polygon grown by tol: holds the curve's tol-neighbourhood
    double speed = 0;      // bound on |C'(u)|
    std::vector<int> xs;   // vertex coordinates on the line, ascending
    std::vector<Vec3> pos; // their curve points
    std::vector<VertexKey> keys; // their vertex keys
};

// Point and derivative at u: de Casteljau on the homogeneous control points.
void evaluate_curve(const Line& c, double u, Vec3& p, Vec3& d) {
    std::array<HPoint, BezierPatch::kMaxOrder> h = c.cp;
    for (int r = 1; r < c.n; ++r)
        for (int i = 0; i <= c.n - r; ++i) h[i] = lerp(h[i], h[i + 1], u);
    const HPoint X = lerp(h[0], h[1], u), dX = static_cast<double>(c.n) * (h[1] - h[0]);
    p = X.point();
    d = (1.0 / X.w) * (dX.xyz() - dX.w * p);
}

Vec3 curve_point(const Line& c, double u) {
    Vec3 p, d;
    evaluate_curve(c, u, p, d);
    return p;
}

// Distance from P to the curve, and in u the parameter of the nearest point:
// the best of a few samples, then Gauss-Newton (the residual is within the
// seam tolerance where it matters, so it converges fast), clamped to [0, 1].
// Points that cannot come within tol (farther from every sample than the
// curve runs in half a sample step) keep the sample distance.
double project(const Line& c, Vec3 P, double tol, double& u) {
    const int samples = std::max(8, 2 * c.n);
    double best = std::numeric_limits<double>::infinity();
    for (int k = 0; k <= samples; ++k) {
        const double x = static_cast<double>(k) / samples;
        const double d = distance(curve_point(c, x), P);
        if (d < best) best = d, u = x;
    }
    if (best > tol + c.speed * 0.5 / samples) return best;
    for (int it = 0; it < 50; ++it) {
        Vec3 p, d;
        evaluate_curve(c, u, p, d);
        const double dd = dot(d, d);
        if (!(dd > 0)) break;
        const double next = std::clamp(u + dot(P - p, d) / dd, 0.0, 1.0);
        const bool done = std::abs(next - u) <= 1e-15;
        u = next;
        if (done) break;
    }
    return std::min(best, distance(curve_point(c, u), P));
}

bool near_curve(const Line& c, Vec3 P, double tol) {
    double u = 0;
    return c.box.contains(P) && project(c, P, tol, u) <= tol;
}

Line make_line(const std::vector<BezierPatch>& patches, const BoundaryMatch& m,
               const EdgeRegistry& reg, int id, double tol) {
    Line L;
    L.id = id;
    const int ref = m.group_ref[id], patch = ref / 4, e = ref % 4;
    const BezierPatch& b = patches[patch];
    L.n = edge_order(b, e);
    for (int k = 0; k <= L.n; ++k) {
        L.cp[k] = edge_control(b, e, k);
        L.box.extend(L.cp[k].point());
    }
    // |C'| <= n (w_max / w_min)^2 max |P_k+1 - P_k| (Floater's bound for
    // rational Bezier curves; the plain one when the weights are equal).
    double wmin = L.cp[0].w, wmax = L.cp[0].w, step = 0;
    for (int k = 1; k <= L.n; ++k) {
        wmin = std::min(wmin, L.cp[k].w), wmax = std::max(wmax, L.cp[k].w);
        step = std::max(step, distance(L.cp[k].point(), L.cp[k - 1].point()));
    }
    L.speed = L.n * (wmax / wmin) * (wmax / wmin) * step;
    L.box.lo = L.box.lo - Vec3{tol, tol, tol};
    L.box.hi = L.box.hi + Vec3{tol, tol, tol};
    for (int i = reg.offsets[id]; i < reg.offsets[id + 1]; ++i) {
        L.xs.push_back(reg.segments[i].a);
        L.xs.push_back(reg.segments[i].b);
    }
    std::sort(L.xs.begin(), L.xs.end());
    L.xs.erase(std::unique(L.xs.begin(), L.xs.end()), L.xs.end());
    for (int x : L.xs) {
        int s = 0, t = 0;
        edge_grid_point(e, x, s, t);
        L.keys.push_back(vertex_key(m, patch, s, t));
        L.pos.push_back(x == 0           ? L.cp[0].point()
                        : x == kParamOne ? L.cp[L.n].point()
                                         : curve_point(L, param_of(x)));
    }
    return L;
}

// Union-find over vertex keys; the first key seen represents its class.
struct KeyClasses {
    std::unordered_map<VertexKey, int, VertexKeyHash> id;
    std::vector<VertexKey> key;
    DisjointSets sets{0};

    int of(VertexKey k) {
        auto [it, fresh] = id.try_emplace(k, static_cast<int>(key.size()));
        if (fresh) {
            key.push_back(k);
            sets.parent.push_back(it->second);
        }
        return it->second;
    }
    int find(int x) { return sets.find(x); }
    void unite(int a, int b) { sets.unite(a, b); }
    VertexKey rep(VertexKey k) {
        auto it = id.find(k);
        return it == id.end() ? k : key[find(it->second)];
    }
};

struct Candidate {
    int line = -1;
    double x = 0;
    VertexKey key;
};

// H's vertices on G: aliases for those within tol of a vertex of G, candidates
// for insertion for the others. True when the curves share a piece.
bool match_into(const Line& G, const Line& H, double tol, KeyClasses& classes,
                std::vector<Candidate>& out) {
    bool shared = false;
    const int nh = static_cast<int>(H.xs.size()), ng = static_cast<int>(G.xs.size());
    for (int k = 0; k < nh; ++k) {
        const Vec3 P = H.pos[k];
        if (!G.box.contains(P)) continue;
        double y = 0;
        if (project(G, P, tol, y) > tol) continue;
        // G's vertices around y: one within tol of P (at most), and the
        // neighbours on either side apart from it.
        const int i0 =
            static_cast<int>(std::lower_bound(G.xs.begin(), G.xs.end(), y,
                                              [](int x, double v) { return param_of(x) < v; }) -
                             G.xs.begin());
        int near = -1;
        double near_d = tol;
        for (int i : {i0 - 1, i0})
            if (i >= 0 && i < ng && distance(G.pos[i], P) <= near_d)
                near = i, near_d = distance(G.pos[i], P);
        int lo = i0 - 1, hi = i0;
        if (lo == near) --lo;
        if (hi == near) ++hi;
        // The curves agree next to P: the shared piece ends at a vertex of G
        // or of H, so the midpoint towards the nearer of those lies on both.
        bool along = false;
        const double xk = param_of(H.xs[k]);
        for (int nb : {k - 1, k + 1})
            if (!along && nb >= 0 && nb < nh)
                along = near_curve(G, curve_point(H, 0.5 * (xk + param_of(H.xs[nb]))), tol);
        for (int nb : {lo, hi})
            if (!along && nb >= 0 && nb < ng)
                along = near_curve(H, curve_point(G, 0.5 * (y + param_of(G.xs[nb]))), tol);
        if (!along) continue;
        shared = true;
        if (near >= 0)
            classes.unite(classes.of(H.keys[k]), classes.of(G.keys[near]));
        else
            out.push_back({G.id, y, H.keys[k]});
    }
    return shared;
}

} // namespace

EdgeGraph build_edge_graph(const std::vector<BezierPatch>& patches, const BoundaryMatch& m,
                           const EdgeRegistry& reg, double tol) {
    EdgeGraph g;
    const int nlines = static_cast<int>(m.group_ref.size());
    g.offsets.assign(nlines + 1, 0);
    // Edges paired by their control polygons are done (two sides each).
    std::vector<Line> lines;
    std::vector<int> line_of(nlines, -1);
    for (int id = 0; id < nlines; ++id)
        if (m.group_size[id] == 1) {
            line_of[id] = static_cast<int>(lines.size());
            lines.push_back(make_line(patches, m, reg, id, tol));
        }

    // Pairs with overlapping boxes (sweep in x), in both directions.
    std::vector<int> order(lines.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
    std::sort(order.begin(), order.end(),
              [&](int a, int b) { return lines[a].box.lo.x < lines[b].box.lo.x; });
    KeyClasses classes;
    std::vector<Candidate> cands;
    for (size_t i = 0; i < order.size(); ++i) {
        const Line& A = lines[order[i]];
        for (size_t j = i + 1; j < order.size() && lines[order[j]].box.lo.x <= A.box.hi.x; ++j) {
            const Line& B = lines[order[j]];
            if (B.box.lo.y > A.box.hi.y || A.box.lo.y > B.box.hi.y || B.box.lo.z > A.box.hi.z ||
                A.box.lo.z > B.box.hi.z)
                continue;
            const bool ab = match_into(A, B, tol, classes, cands);
            const bool ba = match_into(B, A, tol, classes, cands);
            if (ab || ba) ++g.seams;
        }
    }

    // Representatives; a candidate that is (an alias of) a vertex of its
    // line already, or repeats one inserted before, is not inserted again.
    for (int c = 0; c < static_cast<int>(classes.key.size()); ++c) {
        const int root = classes.find(c);
        if (root == c) continue;
        g.alias.emplace(classes.key[c], classes.key[root]);
        ++g.seam_vertices;
    }
    std::stable_sort(cands.begin(), cands.end(), [](const Candidate& a, const Candidate& b) {
        return a.line != b.line ? a.line < b.line : a.x < b.x;
    });
    for (size_t i = 0; i < cands.size();) {
        const int id = cands[i].line;
        const Line& L = lines[line_of[id]];
        std::unordered_set<VertexKey, VertexKeyHash> seen;
        for (const VertexKey& k : L.keys) seen.insert(classes.rep(k));
        for (; i < cands.size() && cands[i].line == id; ++i) {
            const VertexKey r = classes.rep(cands[i].key);
            if (!seen.insert(r).second) continue;
            g.points.push_back({cands[i].x, r});
            ++g.offsets[id + 1];
            ++g.seam_vertices;
        }
    }
    for (int l = 0; l < nlines; ++l) g.offsets[l + 1] += g.offsets[l];
    return g;
}

} // namespace seamless
