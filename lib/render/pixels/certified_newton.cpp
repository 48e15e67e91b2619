// SPDX-License-Identifier: MIT
// Certified Newton for one ray and one patch in a box (certified_newton.h).
#include <seamless/render/pixels/certified_newton.h>

#include <seamless/interval/hansen_sengupta.h>
#include <seamless/spline/fixed_degree.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace seamless {

bool newton_step(const SurfacePoint& sp, double a, double b, double& s, double& t, double& step) {
    const double f0 = sp.point.x - a * sp.point.z, f1 = sp.point.y - b * sp.point.z;
    const double j00 = sp.du.x - a * sp.du.z, j01 = sp.dv.x - a * sp.dv.z;
    const double j10 = sp.du.y - b * sp.du.z, j11 = sp.dv.y - b * sp.dv.z;
    const double det = j00 * j11 - j01 * j10;
    if (!(std::abs(det) > 0)) return false;
    const double ds = (f0 * j11 - f1 * j01) / det, dt = (j00 * f1 - j10 * f0) / det;
    s -= ds;
    t -= dt;
    step = std::abs(ds) + std::abs(dt);
    return std::isfinite(step);
}

namespace {

// [lo, hi] computed in doubles (round to nearest) by at most a few sums and
// products of terms whose magnitudes add up to at most `size`, moved outward
// by 2e-15 size (more than the five roundings' 5.6e-16 size such a chain can
// err by) and an allowance for underflow: an enclosure of the exact bounds,
// at a quarter of the interval operations' cost. Entire where not finite.
Interval widened(double lo, double hi, double size) {
    const double slack = 2e-15 * size + underflow_allowance(8);
    const Interval r(lo - slack, hi + slack);
    return r.is_finite() ? r : Interval::entire();
}

bool newton_step(const BezierPatch& p, double a, double b, double& s, double& t, double& step) {
    return newton_step(evaluate(p, s, t), a, b, s, t, step);
}

// The interval Jacobian of G over a box.
IMat<2> jacobian(const ClusterSystem& sys, const ParamBox& box) {
    IMat<2> A;
    for (int k = 0; k < 2; ++k) {
        A(k, 0) = horner(sys.Gs, k, box);
        A(k, 1) = horner(sys.Gt, k, box);
    }
    return A;
}

// ||I - C A||_inf < 1 with C = mid(A)^-1: every matrix of A is regular.
// J.C and J.CA are set for J.step (C = I where mid(A) is singular), J.E
// for krawczyk_hit. C A in doubles: each entry's bounds are the sums of the
// products' bounds, widened (the interval products cost four times as much).
bool regular(MarkJacobian& J) {
    J.preconditioned = invert<2>(mid(J.A), J.C);
    if (!J.preconditioned) {
        J.C = identity_matrix<2>();
        J.CA = J.A;
        return false;
    }
    bool below = true;
    for (int i = 0; i < 2; ++i) {
        double row = 0;
        for (int k = 0; k < 2; ++k) {
            double lo = 0, hi = 0, size = 0;
            for (int j = 0; j < 2; ++j) {
                const double c = J.C[i * 2 + j];
                const double p = c * J.A(j, k).lo(), q = c * J.A(j, k).hi();
                lo += std::min(p, q);
                hi += std::max(p, q);
                size += std::max(std::abs(p), std::abs(q));
            }
            J.CA(i, k) = widened(lo, hi, size);
            J.E[i * 2 + k] = (Interval(i == k ? 1.0 : 0.0) - J.CA(i, k)).mag();
            row += J.E[i * 2 + k];
        }
        below &= next_up(row) < 1;
    }
    return below;
}

// Camera depth Z = X_2 / W over the small box of a certified hit, by the mean
// value theorem about a point c of [0,1]^2: X_k(x) - X_k(c) = grad X_k(xi) .
// (x - c) with xi in [0,1]^2, where |d X_k / ds| <= pp.slope_s[k], likewise
// along t (projection.h). Xc: X_k(c) enclosed (enclose_homogeneous; X_3 = W
// when rational). For a box of width ~1e-9 this is narrow enough to order
// hits and far cheaper than a range enclosure over it.
Interval depth_over(const ProjectedPatch& pp, const ParamBox& hit, double cs, double ct,
                    const Interval* Xc) {
    // |x - c| over the box, rounded up; then Xc +- (slope_s ds + slope_t dt), widened.
    const double ds = next_up(std::max(cs - hit.s.lo(), hit.s.hi() - cs));
    const double dt = next_up(std::max(ct - hit.t.lo(), hit.t.hi() - ct));
    auto over = [&](int c) {
        const double r = pp.slope_s[c] * ds + pp.slope_t[c] * dt;
        return widened(Xc[c].lo() - r, Xc[c].hi() + r, Xc[c].mag() + r);
    };
    const Interval Z = over(2);
    if (!pp.forms.rational) return Z;
    return Z / intersect(over(3), pp.forms.w_hull);
}

// Newton's step on the homogeneous system G = (X - a Z, Y - b Z) (the same
// zeros as on X / W, W > 0): bicubic, biquadratic and bilinear patches by
// ray_system_fixed, without the quotient rule and with the sums over two
// combined coordinates (Newton's point only steers, the certificate is below).
[[gnu::always_inline]] inline bool ray_step(const BezierPatch& p, double a, double b, double& s,
                                            double& t, double& step) {
    RaySystemAt g;
    if (p.p == 3 && p.q == 3)
        g = ray_system_fixed<3, 3>(p, a, b, s, t);
    else if (p.p == 2 && p.q == 2)
        g = ray_system_fixed<2, 2>(p, a, b, s, t);
    else if (p.p == 1 && p.q == 1)
        g = ray_system_fixed<1, 1>(p, a, b, s, t);
    else
        return newton_step(p, a, b, s, t, step);
    const double *G = g.G, *Gs = g.Gs, *Gt = g.Gt;
    const double det = Gs[0] * Gt[1] - Gt[0] * Gs[1];
    if (!(std::abs(det) > 0)) return false;
    const double ds = (G[0] * Gt[1] - G[1] * Gt[0]) / det, dt = (Gs[0] * G[1] - Gs[1] * G[0]) / det;
    s -= ds;
    t -= dt;
    step = std::abs(ds) + std::abs(dt);
    return std::isfinite(step);
}
} // namespace

bool ray_newton_step(const BezierPatch& p, double a, double b, double& s, double& t, double& step) {
    return ray_step(p, a, b, s, t, step);
}

IVec<2> RaySystem::at(double s, double t) const {
    Interval X[3];
    enclose_homogeneous(pp_.patch, s, t, 3, X);
    return at(X);
}

IVec<2> RaySystem::at(const Interval* X) const {
    IVec<2> G;
    const double e[2] = {a_, b_};
    for (int i = 0; i < 2; ++i) {
        const double p = e[i] * X[2].lo(), q = e[i] * X[2].hi();
        G[i] = widened(X[i].lo() - std::max(p, q), X[i].hi() - std::min(p, q),
                       X[i].mag() + std::max(std::abs(p), std::abs(q)));
    }
    return G;
}

const ClusterSystem& RaySystem::forms() {
    if (!built_) {
        cluster_system(pp_.forms, Interval(a_), Interval(b_), sys_);
        if (of_) *of_ = {&pp_, a_, b_};
    }
    built_ = true;
    return sys_;
}

MarkJacobian mark_jacobian(const ClusterSystem& sys, const ParamBox& box) {
    return mark_jacobian(jacobian(sys, box));
}

MarkJacobian mark_jacobian(const IMat<2>& A) {
    MarkJacobian j;
    j.A = A;
    j.regular = regular(j);
    return j;
}

namespace {

// K = c - C G(c) + (I - C A)(Y - c) of krawczyk_hit in doubles (I - C A
// bounded by J.E), widened. false where a value is not finite.
bool krawczyk_box(const MarkJacobian& J, const IVec<2>& Gc, const IVec<2>& Y, const RVec<2>& c,
                  Interval K[2]) {
    double R[2]; // the largest distance from c to Y's ends, rounded up
    for (int k = 0; k < 2; ++k) R[k] = next_up(std::max(c[k] - Y[k].lo(), Y[k].hi() - c[k]));
    for (int i = 0; i < 2; ++i) {
        double lo = 0, hi = 0, size = 0; // C G(c) and the magnitude of its terms
        for (int k = 0; k < 2; ++k) {
            const double p = J.C[i * 2 + k] * Gc[k].lo(), q = J.C[i * 2 + k] * Gc[k].hi();
            lo += std::min(p, q);
            hi += std::max(p, q);
            size += std::max(std::abs(p), std::abs(q));
        }
        const double er = J.E[i * 2] * R[0] + J.E[i * 2 + 1] * R[1];
        K[i] = widened(c[i] - hi - er, c[i] - lo + er, std::abs(c[i]) + size + er);
        if (!K[i].is_finite()) return false;
    }
    return true;
}

} // namespace

bool krawczyk_hit(const MarkJacobian& J, const IVec<2>& Gc, const IVec<2>& Y, const RVec<2>& c,
                  ParamBox& hit) {
    Interval K[2];
    if (!J.regular || !krawczyk_box(J, Gc, Y, c, K)) return false;
    for (int i = 0; i < 2; ++i)
        if (!Y[i].contains_in_interior(K[i])) return false;
    hit = {K[0], K[1]};
    return true;
}

bool newton_hit(RaySystem& sys, const ParamBox& box, const MarkJacobian& J, CertifiedHit& out,
                RenderStats& st, NewtonStart from, NewtonFrame* frame) {
    const ProjectedPatch& pp = sys.patch();
    const double a = sys.a(), b = sys.b();
    const double* start = from.st;
    const SurfacePoint* at_start = from.at;
    ParamBox& hit = out.box;
    Interval& q = out.q;
    // At most one zero in box when A is regular: Newton in doubles from
    // `start` or the box's centre; a run whose step leaves the box (mostly
    // the ray passing beside the patch) stops there, and the ray goes on to
    // the miss proof and the clip (rather than after a few steps clamped to
    // the box, which mostly lead nowhere).
    if (!J.regular) return false;
    double s = box.s.mid(), t = box.t.mid(), step = 1;
    if (start) {
        s = std::clamp(start[0], box.s.lo(), box.s.hi());
        t = std::clamp(start[1], box.t.lo(), box.t.hi());
    }
    if (!start || s != start[0] || t != start[1]) at_start = nullptr; // not evaluated there
    // It stops once the point is far closer to the zero than the inflation's
    // 1e-9: a step below 1e-10, or one whose size d after a step of size p
    // puts the next error, by quadratic convergence about (d / p^2) d^2,
    // below 1e-11 (which saves the last evaluation of most runs). No
    // certificate rests on this: where the point is not that close, the step
    // below fails and the ray goes on to the clip.
    bool converged = false;
    for (int it = 0, prev = 0; it < 16 && !converged; ++it) {
        const double last = step;
        // The first step on P = X / W, from the kept evaluation where there
        // is one (the same bits either way), the later ones on G.
        if (!(it == 0 ? at_start ? newton_step(*at_start, a, b, s, t, step)
                                 : newton_step(pp.patch, a, b, s, t, step)
                      : ray_step(pp.patch, a, b, s, t, step)))
            break;
        if (!box.s.contains(s) || !box.t.contains(t)) break;
        converged =
            step <= 1e-10 || (prev && step <= 1e-5 && step * step * step < 1e-11 * last * last);
        prev = 1;
    }
    if (!converged) return false;
    // Epsilon inflation, then Theorem 6 iii on the small box Y: one zero
    // in Y, so the only zero in box.
    const double e = 1e-9;
    const IVec<2> Y{{intersect(Interval(next_down(s - e), next_up(s + e)), box.s),
                     intersect(Interval(next_down(t - e), next_up(t + e)), box.t)}};
    // X at Newton's point: G there for the step, and the centre of the depth's mean value form.
    Interval X[4];
    if (frame) {
        enclose_homogeneous(pp.patch, s, t, pp.forms.rational ? 4 : 3, X, frame->at);
        frame->s = s;
        frame->t = t;
    } else {
        enclose_homogeneous(pp.patch, s, t, pp.forms.rational ? 4 : 3, X);
    }
    const IVec<2> F = sys.at(X);
    // A over the box bounds G' over Y too; only where it is too wide to
    // certify is the Jacobian enclosed over Y itself.
    ++st.hs_steps;
    if (krawczyk_hit(J, F, Y, RVec<2>{s, t}, hit)) {
        q = depth_over(pp, hit, s, t, X); // camera z = X_2 / W over the hit's box
        return true;
    }
    HansenSenguptaStep<2> hs = J.step(F, Y, RVec<2>{s, t});
    if (!hs.unique) {
        hs = hansen_sengupta<2>(jacobian(sys.forms(), ParamBox{Y[0], Y[1]}), F, Y, RVec<2>{s, t});
        ++st.hs_steps;
    }
    if (!hs.unique) return false;
    hit = {hs.box[0], hs.box[1]};
    q = depth_over(pp, hit, s, t, X); // camera z = X_2 / W over the hit's box
    return true;
}

NewtonOutcome newton_certified(RaySystem& sys, const ParamBox& box, CertifiedHit& hit,
                               RenderStats& st, const MarkJacobian* given, ParamBox* rest,
                               const double* start) {
    MarkJacobian own;
    const MarkJacobian& J = given ? *given : (own = mark_jacobian(sys.forms(), box));
    if (newton_hit(sys, box, J, hit, st, {start, nullptr})) return NewtonOutcome::hit;
    ParamBox part;
    if (!may_hold_zero(sys, J, box, part, st)) return NewtonOutcome::miss;
    if (rest) *rest = part;
    return NewtonOutcome::undecided;
}

bool may_hold_zero(const RaySystem& sys, const MarkJacobian& J, const ParamBox& box, ParamBox& rest,
                   RenderStats& st, const Interval* Xc) {
    // One Hansen-Sengupta step over the whole box; empty means no zero
    // there (Theorem 6 ii).
    const IVec<2> X{{box.s, box.t}};
    const RVec<2> c = mid(X);
    const IVec<2> Fc = Xc ? sys.at(Xc) : sys.at(c[0], c[1]);
    // Krawczyk's K(X) holds every zero in X too, for any C (J.E is set
    // wherever C = mid(A)^-1, regular or not): where it misses X, there is
    // none, without the Hansen-Sengupta step (which stays the stronger test).
    Interval K[2];
    if (J.preconditioned && krawczyk_box(J, Fc, X, c, K) &&
        (intersect(K[0], X[0]).is_empty() || intersect(K[1], X[1]).is_empty())) {
        ++st.hs_steps;
        return false;
    }
    const HansenSenguptaStep<2> whole = J.step(Fc, X, c);
    ++st.hs_steps;
    if (whole.box.is_empty()) return false;
    rest = {whole.box[0], whole.box[1]}; // every zero in box is here (Theorem 6 i)
    return true;
}

bool newton_in_box(const BezierPatch& patch, double a, double b, const ParamBox& box,
                   const NewtonRun& from, bool along, NewtonRun& to) {
    // 12 steps at most; 1e-9: a step this small near the regular zero (the
    // certificate's Jacobian is regular on box) leaves an error of its
    // square's order (1e-12 cost one more evaluation per pixel for the same
    // images). Or a step
    // d <= 1e-5 whose successor k d^2 would be below 1e-12: the point is then
    // that close to the zero, closer than a single pixel's shading point (the
    // middle of newton_hit's Krawczyk box, inside a 2e-9 wide box). k from a
    // step above 1e-7 (d_i / d_{i-1}^2, at least 1, so that one lucky step
    // does not stop the next runs early).
    constexpr int kSteps = 12;
    constexpr double kConverged = 1e-9, kQuadratic = 1e-5, kPredicted = 1e-12, kMeasurable = 1e-7,
                     kLeast = 1;
    double s = from.s, t = from.t, step = 0;
    if (!newton_step(from.at, a, b, s, t, step)) return false;
    const double s1 = s, t1 = t;
    if (along && from.along) {
        s += from.ds;
        t += from.dt;
    }
    double k = from.k, prev = 0;
    for (int it = 1; it < kSteps; ++it) {
        if (!box.s.contains(s) || !box.t.contains(t)) return false;
        if (!ray_newton_step(patch, a, b, s, t, step)) return false;
        if (prev > kMeasurable) k = std::max(kLeast, step / (prev * prev));
        if (step < kConverged || (step <= kQuadratic && k * step * step < kPredicted)) {
            if (!box.s.contains(s) || !box.t.contains(t)) return false;
            to.s = s; // to.at is the caller's to fill
            to.t = t;
            to.ds = s - s1;
            to.dt = t - t1;
            to.k = k;
            to.along = along;
            return true;
        }
        prev = step;
    }
    return false;
}

bool newton_corner(const BezierPatch& b, double a, double bb, const ParamBox& box, double& s,
                   double& t) {
    const double s0 = box.s.mid(), t0 = box.t.mid();
    NewtonRun hit;
    if (!newton_in_box(b, a, bb, box, NewtonRun{s0, t0, evaluate(b, s0, t0)}, false, hit))
        return false;
    s = hit.s;
    t = hit.t;
    return true;
}

} // namespace seamless
