// SPDX-License-Identifier: MIT
#include <seamless/spline/knot_insertion.h>

#include <seamless/base/check.h>

namespace seamless {
namespace {

// One insertion of the knot t into the knot vector U of degree p, in span k
// (insertion_span), on sequences of n control points.
struct Insertion {
    const std::vector<double>& U;
    int p, k, n;
    double t;
};

// Boehm's insertion on one strided sequence of n control points, P[i * stride]
// into the n + 1 points Q[i * stride]:
// Q_i = P_i (i <= k-p), (1-a_i) P_{i-1} + a_i P_i (k-p < i <= k), P_{i-1} (i > k),
// a_i = (t - t_i) / (t_{i+p} - t_i). The denominators are positive because the
// span k is non-empty and t_i <= t_k < t_{k+1} <= t_{i+p}.
void boehm(const Insertion& in, const HPoint* P, HPoint* Q, int stride) {
    const int p = in.p, k = in.k;
    const std::vector<double>& U = in.U;
    for (int i = 0; i <= k - p; ++i) Q[i * stride] = P[i * stride];
    for (int i = k - p + 1; i <= k; ++i) {
        double a = (in.t - U[i]) / (U[i + p] - U[i]);
        Q[i * stride] = lerp(P[(i - 1) * stride], P[i * stride], a);
    }
    for (int i = k + 1; i <= in.n; ++i) Q[i * stride] = P[(i - 1) * stride];
}

// Distinct knot values within [lo, hi].
std::vector<double> distinct_in(const std::vector<double>& U, double lo, double hi) {
    std::vector<double> out;
    for (double t : U)
        if (t >= lo && t <= hi && (out.empty() || out.back() != t)) out.push_back(t);
    return out;
}

int multiplicity(const std::vector<double>& U, double t) {
    int m = 0;
    for (double x : U) m += (x == t);
    return m;
}

// Span index for insertion: the largest k in [p, n-1] with t_k <= t and t_k < t_{k+1}.
int insertion_span(int p, int n, const std::vector<double>& U, double t) {
    for (int k = n - 1; k > p; --k)
        if (U[k] <= t && U[k] < U[k + 1]) return k;
    return p;
}

} // namespace

HomogeneousNet homogeneous_net(const BSplineSurface& s) {
    HomogeneousNet net;
    net.degree_u = s.degree_u;
    net.degree_v = s.degree_v;
    net.rows = s.size_u;
    net.cols = s.size_v;
    net.knots_u = s.knots_u;
    net.knots_v = s.knots_v;
    net.cp.resize(static_cast<size_t>(net.rows) * net.cols);
    for (int i = 0; i < net.rows; ++i)
        for (int j = 0; j < net.cols; ++j) net.at(i, j) = s.hpoint(i, j);
    return net;
}

void insert_knot_u(HomogeneousNet& net, double t) {
    const int p = net.degree_u, n = net.rows;
    const int k = insertion_span(p, n, net.knots_u, t);
    std::vector<HPoint> out(static_cast<size_t>(n + 1) * net.cols);
    const Insertion in{net.knots_u, p, k, n, t};
    for (int j = 0; j < net.cols; ++j) boehm(in, &net.cp[j], &out[j], net.cols);
    net.cp = std::move(out);
    net.knots_u.insert(net.knots_u.begin() + k + 1, t);
    net.rows = n + 1;
}

void insert_knot_v(HomogeneousNet& net, double t) {
    const int q = net.degree_v, n = net.cols;
    const int k = insertion_span(q, n, net.knots_v, t);
    std::vector<HPoint> out(static_cast<size_t>(net.rows) * (n + 1));
    const Insertion in{net.knots_v, q, k, n, t};
    for (int i = 0; i < net.rows; ++i)
        boehm(in, &net.cp[static_cast<size_t>(i) * n], &out[static_cast<size_t>(i) * (n + 1)], 1);
    net.cp = std::move(out);
    net.knots_v.insert(net.knots_v.begin() + k + 1, t);
    net.cols = n + 1;
}

int bezier_patch_count(const BSplineSurface& s) {
    auto spans = [](int p, int n, const std::vector<double>& U) {
        int c = 0;
        for (int k = p; k < n; ++k) c += U[k] < U[k + 1];
        return c;
    };
    return spans(s.degree_u, s.size_u, s.knots_u) * spans(s.degree_v, s.size_v, s.knots_v);
}

std::vector<BezierPatch> bezier_patches(const BSplineSurface& s, int surface_index) {
    HomogeneousNet net = homogeneous_net(s);
    const int p = s.degree_u, q = s.degree_v;
    for (double t : distinct_in(s.knots_u, s.u_min(), s.u_max()))
        for (int m = multiplicity(net.knots_u, t); m < p; ++m) insert_knot_u(net, t);
    for (double t : distinct_in(s.knots_v, s.v_min(), s.v_max()))
        for (int m = multiplicity(net.knots_v, t); m < q; ++m) insert_knot_v(net, t);

    bool rational = false;
    for (double w : s.weights) rational |= (w != 1.0);

    // Spans of the refined vectors inside the domain. With multiplicity >= degree
    // at both ends of a span k, its control points k-p..k are its Bezier points.
    std::vector<BezierPatch> out;
    out.reserve(static_cast<size_t>(bezier_patch_count(s))); // no copies by doubling
    const double umin = s.u_min(), umax = s.u_max(), vmin = s.v_min(), vmax = s.v_max();
    for (int ku = p; ku < net.rows; ++ku) {
        if (!(net.knots_u[ku] < net.knots_u[ku + 1])) continue;
        if (net.knots_u[ku] < umin || net.knots_u[ku + 1] > umax) continue;
        for (int kv = q; kv < net.cols; ++kv) {
            if (!(net.knots_v[kv] < net.knots_v[kv + 1])) continue;
            if (net.knots_v[kv] < vmin || net.knots_v[kv + 1] > vmax) continue;
            BezierPatch b;
            b.p = p;
            b.q = q;
            b.rational = rational;
            b.surface = surface_index;
            b.u0 = net.knots_u[ku];
            b.u1 = net.knots_u[ku + 1];
            b.v0 = net.knots_v[kv];
            b.v1 = net.knots_v[kv + 1];
            for (int i = 0; i <= p; ++i)
                for (int j = 0; j <= q; ++j) b.at(i, j) = net.at(ku - p + i, kv - q + j);
            out.push_back(b);
        }
    }
    SEAMLESS_CHECK(static_cast<int>(out.size()) == bezier_patch_count(s),
                   "one Bezier patch per non-empty knot span rectangle");
    return out;
}

} // namespace seamless
