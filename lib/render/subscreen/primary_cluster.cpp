// SPDX-License-Identifier: MIT
#include <seamless/render/subscreen/primary_cluster.h>

#include <seamless/base/check.h>
#include <seamless/interval/hansen_sengupta.h>
#include <seamless/interval/lanes.h>

#include <cmath>
#include <limits>

namespace seamless {

namespace {

// (X - a Z, Y - b Z) of a power form's coordinates, written only for f's
// degrees (combine() of power_form.h for this system, without its generic
// loop: one multiplication and one subtraction per coefficient). f and g share
// the degrees, so coordinate c of either is the n = (p + 1) (q + 1)
// coefficients from at(c, 0, 0) on (power_form.h's packing), walked in the
// order (i, j): one index, no per-coefficient address arithmetic.
void primary_rows(const PowerForm& f, Interval a, Interval b, PowerForm& g) {
    g.set_degrees(f.p, f.q, 2);
    const int n = (f.p + 1) * (f.q + 1);
    const Interval *x = &f.at(0, 0, 0), *y = &f.at(1, 0, 0), *z = &f.at(2, 0, 0);
    Interval *g0 = &g.at(0, 0, 0), *g1 = &g.at(1, 0, 0);
    for (int k = 0; k < n; ++k) {
        g0[k] = x[k] - a * z[k];
        g1[k] = y[k] - b * z[k];
    }
}

} // namespace

void cluster_system(const PatchForms& f, Interval a, Interval b, ClusterSystem& out) {
    primary_rows(f.X, a, b, out.G);
    primary_rows(f.Xs, a, b, out.Gs);
    primary_rows(f.Xt, a, b, out.Gt);
    out.X = &f.X;
    out.a = a;
    out.b = b;
}

int solve_pieces(Interval n, Interval d, Interval X, double x0, Interval out[2]) {
    const Interval rel = X - Interval(x0);
    if (!d.contains(0.0)) {
        out[0] = intersect(Interval(x0) + (-n) / d, X);
        return out[0].is_empty() ? 0 : 1;
    }
    if (n.contains(0.0)) {
        out[0] = X;
        return 1;
    }
    // -n / d with 0 in d: two half-lines, or one when d touches 0 from one side.
    constexpr double inf = std::numeric_limits<double>::infinity();
    const Interval num = -n;
    Interval left = Interval::empty(), right = Interval::empty();
    if (num.lo() > 0) {
        if (d.hi() > 0) right = {next_down(num.lo() / d.hi()), inf};
        if (d.lo() < 0) left = {-inf, next_up(num.lo() / d.lo())};
    } else {
        if (d.hi() > 0) left = {-inf, next_up(num.hi() / d.hi())};
        if (d.lo() < 0) right = {next_down(num.hi() / d.lo()), inf};
    }
    int k = 0;
    for (Interval piece : {intersect(left, rel), intersect(right, rel)})
        if (!piece.is_empty()) out[k++] = intersect(Interval(x0) + piece, X);
    return k;
}

bool narrow(const ClusterSystem& sys, ParamBox& box, IMat<2>* jacobian) {
    for (int pass = 0; pass < 3; ++pass) {
        const double before = box.s.width() * box.t.width();
        for (int k = 0; k < 2; ++k) {
            const Interval Ds = horner(sys.Gs, k, box);
            Interval s = box.s;
            for (double s0 : {box.s.lo(), box.s.hi()}) {
                Interval piece[2];
                const Interval N = horner(sys.G, k, ParamBox{Interval(s0), box.t});
                int n = solve_pieces(N, Ds, s, s0, piece);
                s = n == 0 ? Interval::empty() : (n == 1 ? piece[0] : hull(piece[0], piece[1]));
                if (s.is_empty()) return false;
            }
            box.s = s;
            const Interval Dt = horner(sys.Gt, k, box);
            if (jacobian) {
                (*jacobian)(k, 0) = Ds;
                (*jacobian)(k, 1) = Dt;
            }
            Interval t = box.t;
            for (double t0 : {box.t.lo(), box.t.hi()}) {
                Interval piece[2];
                const Interval N = horner(sys.G, k, ParamBox{box.s, Interval(t0)});
                int n = solve_pieces(N, Dt, t, t0, piece);
                t = n == 0 ? Interval::empty() : (n == 1 ? piece[0] : hull(piece[0], piece[1]));
                if (t.is_empty()) return false;
            }
            box.t = t;
        }
        if (box.s.width() * box.t.width() > 0.8 * before) break;
    }
    return true;
}

int separate(const ClusterSystem& sys, const ParamBox& box, ParamBox out[2]) {
    for (int dir = 0; dir < 2; ++dir) {
        for (int k = 0; k < 2; ++k) {
            Interval piece[2];
            int n;
            if (dir == 0) {
                const double s0 = box.s.mid();
                n = solve_pieces(horner(sys.G, k, ParamBox{Interval(s0), box.t}),
                                 horner(sys.Gs, k, box), box.s, s0, piece);
            } else {
                const double t0 = box.t.mid();
                n = solve_pieces(horner(sys.G, k, ParamBox{box.s, Interval(t0)}),
                                 horner(sys.Gt, k, box), box.t, t0, piece);
            }
            if (n == 0) return 0;
            if (n == 2) {
                out[0] = out[1] = box;
                (dir == 0 ? out[0].s : out[0].t) = piece[0];
                (dir == 0 ? out[1].s : out[1].t) = piece[1];
                return 2;
            }
        }
    }
    out[0] = box;
    return 1;
}

namespace {

// The box widened by a tenth of its widths (and 1e-12) on each side, within
// [0,1]: room for the Hansen-Sengupta image to land in the interior.
Interval inflate(Interval x) {
    const double d = 0.1 * x.width() + 1e-12;
    return intersect(Interval(next_down(x.lo() - d), next_up(x.hi() + d)), Interval(0.0, 1.0));
}

} // namespace

IVec<2> cluster_start(const ParamBox& box) {
    IVec<2> x;
    x[0] = inflate(box.s);
    x[1] = inflate(box.t);
    return x;
}

ClusterCertificate certify_steps(const ClusterSystem& sys, IVec<2>& x, ParamBox& box,
                                 int iterations, long long* steps) {
    for (int iter = 0; iter < iterations; ++iter) {
        IMat<2> A;
        IVec<2> F;
        const ParamBox xb{x[0], x[1]};
        for (int k = 0; k < 2; ++k) {
            A(k, 0) = horner(sys.Gs, k, xb);
            A(k, 1) = horner(sys.Gt, k, xb);
        }
        // A determinant enclosure holding 0 says A may hold a singular matrix
        // (a fold or silhouette inside), and then no step maps the box into
        // its interior (Theorem 6 iii needs every matrix of A regular): stop
        // instead of stepping on. The enclosure overestimates, so this is a
        // cost decision; a false answer only splits B.
        if ((A(0, 0) * A(1, 1) - A(0, 1) * A(1, 0)).contains(0.0))
            return ClusterCertificate::failed;
        // G at the midpoint. G's power form holds [a] in every coefficient, and
        // Horner adds up their widths (3 times the width of X - [a] Z near
        // s, t = 1); X, Y, Z at the point with [a], [b] multiplied once
        // enclose the same values, tighter (fewer clusters fail).
        const double cs = x[0].mid(), ct = x[1].mid();
        const ParamBox xm{Interval(cs), Interval(ct)};
        SEAMLESS_DCHECK(sys.X, "ClusterSystem::X is set with G by cluster_system");
        const Interval Z = horner(*sys.X, 2, xm);
        F[0] = horner(*sys.X, 0, xm) - sys.a * Z;
        F[1] = horner(*sys.X, 1, xm) - sys.b * Z;
        const HansenSenguptaStep<2> step = hansen_sengupta<2>(A, F, x, RVec<2>{cs, ct});
        if (steps) ++*steps;
        if (step.box.is_empty()) return ClusterCertificate::failed;
        if (step.unique) {
            box = {step.box[0], step.box[1]};
            return ClusterCertificate::proven;
        }
        x[0] = inflate(step.box[0]);
        x[1] = inflate(step.box[1]);
    }
    return ClusterCertificate::open;
}

bool certify_cluster(const ClusterSystem& sys, ParamBox& box, long long* steps) {
    IVec<2> x = cluster_start(box);
    return certify_steps(sys, x, box, kClusterCertifySteps, steps) == ClusterCertificate::proven;
}

} // namespace seamless
