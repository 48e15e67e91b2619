// SPDX-License-Identifier: MIT
// Seam cases (issue 9, section 1): models whose surfaces meet along curves
// without sharing a control polygon, built directly as B-spline surfaces. The
// operations change a surface's control net, knots, degree, weights or
// parametrisation and keep its geometry (up to rounding): knot insertion,
// degree elevation, polynomial reparametrisation u -> c u + (1 - c) u^2,
// rational reparametrisation (weights times rho^i), reversal, splitting.
#pragma once

#include <seamless/model/model.h>
#include <seamless/spline/knot_insertion.h>

#include <cmath>
#include <string>
#include <vector>

namespace seamless::test {

// Clamped [0,1] knots of a single Bezier span of degree p.
inline std::vector<double> bezier_knots(int p) {
    std::vector<double> k(p + 1, 0.0);
    k.insert(k.end(), p + 1, 1.0);
    return k;
}

// A Bezier surface (one span each way) from a (p+1) x (q+1) net, row i along u.
inline BSplineSurface bezier_surface(const std::string& name, int p, int q,
                                     const std::vector<Vec3>& points) {
    BSplineSurface s;
    s.name = name;
    s.degree_u = p, s.degree_v = q;
    s.size_u = p + 1, s.size_v = q + 1;
    s.knots_u = bezier_knots(p), s.knots_v = bezier_knots(q);
    s.points = points;
    return s;
}

inline BSplineSurface from_net(const HomogeneousNet& n, const std::string& name) {
    BSplineSurface s;
    s.name = name;
    s.degree_u = n.degree_u, s.degree_v = n.degree_v;
    s.size_u = n.rows, s.size_v = n.cols;
    s.knots_u = n.knots_u, s.knots_v = n.knots_v;
    bool rational = false;
    for (const HPoint& h : n.cp) {
        s.points.push_back(h.point());
        s.weights.push_back(h.w);
        rational = rational || h.w != 1.0;
    }
    if (!rational) s.weights.clear();
    return s;
}

// Transposes the net so that direction v becomes u (the surface's normal flips).
inline HomogeneousNet transposed(const HomogeneousNet& n) {
    HomogeneousNet t;
    t.degree_u = n.degree_v, t.degree_v = n.degree_u;
    t.rows = n.cols, t.cols = n.rows;
    t.knots_u = n.knots_v, t.knots_v = n.knots_u;
    t.cp.resize(n.cp.size());
    for (int i = 0; i < n.rows; ++i)
        for (int j = 0; j < n.cols; ++j) t.at(j, i) = n.at(i, j);
    return t;
}

// Applies `op` to the net along u (dir 0) or v (dir 1).
template <class Op> BSplineSurface along(const BSplineSurface& s, int dir, Op op) {
    HomogeneousNet n = homogeneous_net(s);
    if (dir == 1) n = transposed(n);
    op(n);
    if (dir == 1) n = transposed(n);
    return from_net(n, s.name);
}

// Knot t inserted once (Boehm).
inline BSplineSurface insert_knot(const BSplineSurface& s, int dir, double t) {
    return along(s, dir, [t](HomogeneousNet& n) { insert_knot_u(n, t); });
}

// Rows of a single-span net as Bezier curves; f maps each row list (i = 0..p,
// homogeneous) to the new rows; the new degree is the new size - 1.
template <class F> void map_rows(HomogeneousNet& n, F f) {
    const int p = n.degree_u;
    if (n.rows != p + 1) throw std::logic_error("seam_cases: not a single Bezier span");
    std::vector<HPoint> out;
    int rows = 0;
    for (int j = 0; j < n.cols; ++j) {
        std::vector<HPoint> col(p + 1);
        for (int i = 0; i <= p; ++i) col[i] = n.at(i, j);
        const std::vector<HPoint> c = f(col);
        rows = static_cast<int>(c.size());
        if (j == 0) out.resize(static_cast<size_t>(rows) * n.cols);
        for (int i = 0; i < rows; ++i) out[static_cast<size_t>(i) * n.cols + j] = c[i];
    }
    n.cp = out;
    n.rows = rows;
    n.degree_u = rows - 1;
    n.knots_u = bezier_knots(rows - 1);
}

// Degree elevation by one of a single span: Q_i = i/(p+1) P_{i-1} + (1 - i/(p+1)) P_i.
inline BSplineSurface elevate(const BSplineSurface& s, int dir) {
    return along(s, dir, [](HomogeneousNet& n) {
        map_rows(n, [](const std::vector<HPoint>& P) {
            const int p = static_cast<int>(P.size()) - 1;
            std::vector<HPoint> Q(p + 2);
            for (int i = 0; i <= p + 1; ++i) {
                const double a = static_cast<double>(i) / (p + 1);
                HPoint q{0, 0, 0, 0};
                if (i > 0) q = q + a * P[i - 1];
                if (i <= p) q = q + (1 - a) * P[i];
                Q[i] = q;
            }
            return Q;
        });
    });
}

inline double binomial(int n, int k) {
    double r = 1;
    for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
    return r;
}

// Polynomial reparametrisation u = phi(x) = c x + (1 - c) x^2 of a single
// span, degree p -> 2p: B_i^p(phi(x)) expanded in powers of x, then in the
// Bernstein basis of degree 2p (x^m = sum_k C(k,m)/C(2p,m) B_k^2p). c = 0 is
// u -> u^2.
inline BSplineSurface reparametrise(const BSplineSurface& s, int dir, double c) {
    return along(s, dir, [c](HomogeneousNet& n) {
        map_rows(n, [c](const std::vector<HPoint>& P) {
            const int p = static_cast<int>(P.size()) - 1, q = 2 * p;
            auto mul = [](const std::vector<double>& a, const std::vector<double>& b) {
                std::vector<double> r(a.size() + b.size() - 1, 0.0);
                for (size_t i = 0; i < a.size(); ++i)
                    for (size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
                return r;
            };
            const std::vector<double> phi{0, c, 1 - c}, one_minus{1, -c, c - 1};
            std::vector<HPoint> Q(q + 1, HPoint{0, 0, 0, 0});
            for (int i = 0; i <= p; ++i) {
                std::vector<double> poly{binomial(p, i)};
                for (int k = 0; k < i; ++k) poly = mul(poly, phi);
                for (int k = 0; k < p - i; ++k) poly = mul(poly, one_minus);
                poly.resize(q + 1, 0.0);
                for (int k = 0; k <= q; ++k) {
                    double coeff = 0;
                    for (int m = 0; m <= k; ++m) coeff += poly[m] * binomial(k, m) / binomial(q, m);
                    Q[k] = Q[k] + coeff * P[i];
                }
            }
            return Q;
        });
    });
}

// Rational reparametrisation of a single span: homogeneous points times rho^i
// (same curve, weights rho^i, u -> rho u / (1 - u + rho u)).
inline BSplineSurface rationalise(const BSplineSurface& s, int dir, double rho) {
    return along(s, dir, [rho](HomogeneousNet& n) {
        map_rows(n, [rho](std::vector<HPoint> P) {
            for (size_t i = 0; i < P.size(); ++i)
                P[i] = std::pow(rho, static_cast<double>(i)) * P[i];
            return P;
        });
    });
}

// Reverses u (dir 0) or v (dir 1).
inline BSplineSurface reverse(const BSplineSurface& s, int dir) {
    return along(s, dir, [](HomogeneousNet& n) {
        HomogeneousNet r = n;
        for (int i = 0; i < n.rows; ++i)
            for (int j = 0; j < n.cols; ++j) r.at(i, j) = n.at(n.rows - 1 - i, j);
        const double a = n.knots_u.front(), b = n.knots_u.back();
        for (size_t k = 0; k < n.knots_u.size(); ++k)
            r.knots_u[k] = a + b - n.knots_u[n.knots_u.size() - 1 - k];
        n = r;
    });
}

// The two halves of a single span split at t (each a single span on [0,1]).
inline std::vector<BSplineSurface> split(const BSplineSurface& s, int dir, double t) {
    std::vector<BSplineSurface> out;
    for (int half = 0; half < 2; ++half) {
        BSplineSurface h = along(s, dir, [t, half](HomogeneousNet& n) {
            const int p = n.degree_u;
            for (int k = 0; k < p; ++k) insert_knot_u(n, t);
            HomogeneousNet r = n;
            r.rows = p + 1;
            r.cp.assign(n.cp.begin() + static_cast<long>(half) * p * n.cols,
                        n.cp.begin() + static_cast<long>(half * p + p + 1) * n.cols);
            r.knots_u = bezier_knots(p);
            n = r;
        });
        h.name = s.name + (half ? "/hi" : "/lo");
        out.push_back(h);
    }
    return out;
}

inline BSplineSurface translate(BSplineSurface s, Vec3 d) {
    for (Vec3& p : s.points) p += d;
    return s;
}

// The six faces of a bulged cube: bicubic Bezier patches on the faces of
// [-1,1]^3 pushed outwards (p -> p (1 + 0.25 (1 - |p|^2/3)), the same map on
// both faces of an edge, so neighbours share their boundary control points),
// each oriented outwards. Face order: +x, -x, +y, -y, +z, -z.
inline std::vector<BSplineSurface> bulged_box_faces() {
    const Vec3 X{1, 0, 0}, Y{0, 1, 0}, Z{0, 0, 1};
    struct Face {
        const char* name;
        Vec3 n, a, b; // a x b = n
    };
    const Face faces[6] = {{"+x", X, Y, Z},        {"-x", -1.0 * X, Z, Y}, {"+y", Y, Z, X},
                           {"-y", -1.0 * Y, X, Z}, {"+z", Z, X, Y},        {"-z", -1.0 * Z, Y, X}};
    std::vector<BSplineSurface> out;
    for (const Face& f : faces) {
        std::vector<Vec3> pts;
        for (int i = 0; i <= 3; ++i)
            for (int j = 0; j <= 3; ++j) {
                const Vec3 p = f.n + (-1 + 2.0 * i / 3) * f.a + (-1 + 2.0 * j / 3) * f.b;
                pts.push_back((1 + 0.25 * (1 - dot(p, p) / 3)) * p);
            }
        out.push_back(bezier_surface(f.name, 3, 3, pts));
    }
    return out;
}

inline Model model_of(std::vector<BSplineSurface> surfaces, const std::string& name) {
    Model m;
    m.source = name;
    m.surfaces = std::move(surfaces);
    return m;
}

// A closed seam case: the bulged box with one kind of mismatch on some faces.
struct SeamCase {
    std::string name;
    Model model;
    double seam_tolerance = -1; // TessellationOptions::seam_tolerance
    bool geometric = true;      // needs geometric matching (not only control polygons)
};

inline std::vector<SeamCase> closed_seam_cases() {
    const double r2 = std::sqrt(0.5), golden = (std::sqrt(5.0) - 1) / 2;
    std::vector<SeamCase> out;
    auto box = [&](const std::string& name, auto edit, double tol = -1, bool geometric = true) {
        std::vector<BSplineSurface> f = bulged_box_faces();
        edit(f);
        out.push_back({name, model_of(f, name), tol, geometric});
    };
    box("extra knots at irrational parameters", [&](auto& f) {
        f[4] = insert_knot(insert_knot(f[4], 0, r2), 1, golden); // +z, both ways
        f[0] = insert_knot(f[0], 1, golden);                     // +x
    });
    box("degree elevated", [&](auto& f) {
        f[0] = elevate(f[0], 0);
        f[2] = elevate(elevate(f[2], 1), 0);
    });
    box("reparametrised u -> u^2", [&](auto& f) {
        f[3] = reparametrise(f[3], 0, 0.0);
        f[5] = reparametrise(f[5], 1, 0.5);
    });
    box("reversed direction", [&](auto& f) {
        f[1] = insert_knot(reverse(reverse(f[1], 0), 1), 0, r2); // -x
        f[4] = reverse(reverse(f[4], 0), 1);                     // +z, exact polygons reversed
    });
    box("T-shaped: one edge meets the edges of two surfaces", [&](auto& f) {
        const std::vector<BSplineSurface> halves = split(f[4], 0, r2); // +z in two
        f[4] = halves[0];
        f.push_back(halves[1]);
        const std::vector<BSplineSurface> q = split(f[5], 1, golden); // -z in two, one refined
        f[5] = q[0];
        f.push_back(insert_knot(q[1], 0, 0.3));
    });
    box("rational against polynomial", [&](auto& f) {
        f[2] = rationalise(rationalise(f[2], 0, 2.0), 1, 0.5);
        f[5] = rationalise(f[5], 0, 1.7);
    });
    box(
        "gap of 1e-6 stitched with seam tolerance 1e-5",
        [&](auto& f) {
            f[4] = translate(insert_knot(f[4], 0, r2), {0, 0, 1e-6});
            f[1] = translate(f[1], {-1e-6, 0, 0}); // same net: paired by control polygons
        },
        1e-5);
    box("everything at once", [&](auto& f) {
        f[0] = elevate(insert_knot(f[0], 1, golden), 0);
        f[1] = reverse(reverse(f[1], 0), 1);
        f[2] = rationalise(f[2], 1, 0.6);
        f[3] = reparametrise(f[3], 0, 0.0);
        const std::vector<BSplineSurface> halves = split(insert_knot(f[4], 1, 0.3), 0, r2);
        f[4] = halves[0];
        f.push_back(reverse(reverse(halves[1], 0), 1));
        f[5] = insert_knot(insert_knot(f[5], 0, 0.5), 0, 0.5);
    });
    box(
        "matching control polygons only", [](auto&) {}, -1, false);
    return out;
}

// Two bicubic sheets over [0,1] x [0,1] and [1,2] x [0,1] (z a bump) sharing
// the curve x = 1 exactly; the second gets an extra knot at `knot` along that
// edge (v), then is moved by `gap` in z.
inline Model two_sheets(double knot, double gap = 0) {
    auto sheet = [](const char* name, double x0) {
        std::vector<Vec3> pts;
        for (int i = 0; i <= 3; ++i)
            for (int j = 0; j <= 3; ++j) {
                const double x = x0 + i / 3.0, y = j / 3.0;
                pts.push_back({x, y, 0.3 * std::sin(2 * x + 1) * std::cos(3 * y)});
            }
        return bezier_surface(name, 3, 3, pts);
    };
    BSplineSurface b = sheet("right", 1);
    if (knot > 0) b = insert_knot(b, 1, knot);
    return model_of({sheet("left", 0), translate(b, {0, 0, gap})}, "two sheets");
}

} // namespace seamless::test
