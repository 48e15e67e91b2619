// SPDX-License-Identifier: MIT
#include <seamless/render/pixel_solve.h>
#include <seamless/render/shared_marks.h>

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
// combined coordinates (teapot 640x480 x 16: paint_pixels 423.7 -> 405.0 M
// instructions, PNGs byte-identical; Newton's point only steers, the
// certificate is below).
[[gnu::always_inline]] inline bool ray_step(const BezierPatch& p, double a, double b, double& s,
                                            double& t, double& step) {
    double G[2], Gs[2], Gt[2];
    if (p.p == 3 && p.q == 3)
        ray_system_fixed<3, 3>(p, a, b, s, t, G, Gs, Gt);
    else if (p.p == 2 && p.q == 2)
        ray_system_fixed<2, 2>(p, a, b, s, t, G, Gs, Gt);
    else if (p.p == 1 && p.q == 1)
        ray_system_fixed<1, 1>(p, a, b, s, t, G, Gs, Gt);
    else
        return newton_step(p, a, b, s, t, step);
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

bool newton_hit(const ProjectedPatch& pp, double a, double b, const ParamBox& box, RaySystem& sys,
                const MarkJacobian& J, ParamBox& hit, Interval& q, RenderStats& st,
                const double* start, const SurfacePoint* at_start) {
    // At most one zero in box when A is regular: Newton in doubles from
    // `start` or the box's centre; a run whose step leaves the box (mostly
    // the ray passing beside the patch) stops there, and the ray goes on to
    // the miss proof and the clip. (It stopped after three such steps in a
    // row, each clamped to the box: teapot 640x480 x 16 paint_pixels 497.4 ->
    // 486.4 M instructions stopping at the first, with PNGs byte-identical.)
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
    enclose_homogeneous(pp.patch, s, t, pp.forms.rational ? 4 : 3, X);
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

NewtonOutcome newton_certified(const ProjectedPatch& pp, double a, double b, const ParamBox& box,
                               RaySystem& sys, ParamBox& hit, Interval& q, RenderStats& st,
                               const MarkJacobian* given, ParamBox* rest, const double* start) {
    MarkJacobian own;
    const MarkJacobian& J = given ? *given : (own = mark_jacobian(sys.forms(), box));
    if (newton_hit(pp, a, b, box, sys, J, hit, q, st, start)) return NewtonOutcome::hit;
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

namespace {

// The nearest hit of one ray so far (remark 1): hits with q > 0 taken,
// best_q the upper bound of the nearest depth (marks beyond it are dropped).
struct Nearest {
    PixelHit best;
    double best_q = std::numeric_limits<double>::infinity();
    void take(int patch, const ParamBox& hb, Interval q, int mark = -1) {
        if (!(q.hi() > 0)) return;
        if (best.patch < 0 || q.mid() < best.q)
            best = {patch, hb.s.mid(), hb.t.mid(), q.mid(), best.candidates, mark};
        best_q = std::min(best_q, q.hi());
    }
};

// The covering method of ray_patch.h on a box still undecided.
void cover(const ProjectedPatch& pp, double a, double b, const ParamBox& box, int patch,
           PixelScratch& scratch, RenderStats& st, Nearest& near) {
    scratch.hits.clear();
    RayPatchStats rs;
    intersect(pp.forms, ProjectedScene::primary_ray(a, b), box, scratch.hits, RayPatchOptions{},
              &rs);
    st.hs_iterations += rs.iterations;
    st.hs_steps += rs.iterations;
    if (auto h = nearest_hit(scratch.hits, 0.0)) near.take(patch, h->box, h->q);
}

// A mark's box (or the part of it a clip left): certified Newton; where
// undecided, on the part the Hansen-Sengupta step leaves or its halves (a
// covering method with the cheap test, Jacobians from the ray's power forms),
// and the full covering method only on boxes still undecided at depth 8 (depth
// 6: teapot 640x480 x 16 paint_pixels 452.6 M, 8: 449.2 M, 12 and 16: 448.7 M;
// 8 keeps the worst case at 256 boxes). J and start: the Jacobian over `box`
// and Newton's start for the first step, when known.
void solve_box(const ProjectedPatch& pp, double a, double b, const ParamBox& box0, int patch,
               PixelScratch& scratch, RenderStats& st, Nearest& near,
               const MarkJacobian* J = nullptr, const double* start = nullptr) {
    RaySystem sys(pp, a, b, scratch.sys, scratch.sys_of);
    ++near.best.candidates;
    ++st.pixel_patch_solves;
    constexpr int kDepth = 8;
    auto& todo = scratch.boxes;
    todo.clear();
    todo.push_back({box0, 0});
    while (!todo.empty()) {
        const auto [popped, depth] = todo.back();
        todo.pop_back();
        ParamBox hb;
        Interval q;
        const bool first = depth == 0;
        // Below the first box, the shared Jacobian (enclosed over a box
        // holding this one, so over this one too) where it is regular; a
        // fresh one from the ray's power forms only where that step decided
        // nothing and left most of the box.
        const bool shared = J && (first || J->regular);
        // A shared Jacobian that is not regular still proves misses and
        // contracts the box to where the hits may be (Theorem 6 ii and i hold
        // for any enclosure of G'): its step comes before the fresh
        // Jacobian, which is enclosed over the smaller box (teapot 640x480 x
        // 16: paint_pixels 434.2 -> 427.8 M instructions, PNG byte-identical;
        // the miss proof alone, over the whole box: 432.1 M).
        ParamBox box = popped;
        if (J && !shared && J->preconditioned) {
            if (!may_hold_zero(sys, *J, popped, box, st)) {
                ++st.pixel_newton_certified;
                continue;
            }
        }
        ParamBox rest = box;
        NewtonOutcome nc = newton_certified(pp, a, b, box, sys, hb, q, st, shared ? J : nullptr,
                                            &rest, first ? start : nullptr);
        if (nc == NewtonOutcome::undecided && !first && shared &&
            !(rest.s.width() * rest.t.width() < 0.25 * box.s.width() * box.t.width())) {
            const ParamBox part = rest; // every zero in box is here
            nc = newton_certified(pp, a, b, part, sys, hb, q, st, nullptr, &rest);
        }
        if (nc != NewtonOutcome::undecided) {
            ++st.pixel_newton_certified;
            if (nc == NewtonOutcome::hit) near.take(patch, hb, q);
            continue;
        }
        if (depth < kDepth) {
            // The zeros lie in the Hansen-Sengupta step's box: a box it
            // shrank to below half its area is tried again whole, another one
            // is halved. (Below a quarter: teapot 640x480 x 16 paint_pixels
            // 457.2 M; a tenth 466.0 M, a half 452.6 M, 0.75 452.6 M, 0.9 454.3 M.)
            if (rest.s.width() * rest.t.width() < 0.5 * box.s.width() * box.t.width()) {
                todo.push_back({rest, depth + 1});
                continue;
            }
            ParamBox lo = rest, hi = rest;
            if (rest.s.width() >= rest.t.width()) {
                const double m = rest.s.mid();
                lo.s = {rest.s.lo(), m};
                hi.s = {m, rest.s.hi()};
            } else {
                const double m = rest.t.mid();
                lo.t = {rest.t.lo(), m};
                hi.t = {m, rest.t.hi()};
            }
            todo.push_back({hi, depth + 1});
            todo.push_back({lo, depth + 1});
            continue;
        }
        cover(pp, a, b, box, patch, scratch, st, near);
    }
}

// Mark k of a small sub-screen: Newton on the mark's whole box first, from
// the previous pixel's hit (where the sub-screen's Jacobian is regular a
// certified hit is the only zero in the box, and the ray needs no clip); else
// the ray's own clip of the mark's subpatch (a certain miss, or a smaller box)
// and solve_box there. (Bezier clipping all the way down, restricting the
// subpatch for the one ray, was tried instead of solve_box: fewer
// Hansen-Sengupta steps, but 8% more instructions for the whole render.)
void solve_shared_mark(const ProjectedScene& ps, double a, double b, SharedMarks& shared, size_t k,
                       PixelScratch& scratch, RenderStats& st, Nearest& near) {
    if (shared.refine(k)) {
        // Mark k is now one half, the last mark the other (for the later
        // pixels of B too): this ray is solved on each that it may meet and
        // that is not beyond a hit found already.
        const size_t halves[2] = {k, shared.size() - 1};
        for (const size_t j : halves) {
            const Mark& h = shared.marks()[j];
            if (shared.may_meet_ray(j, a, b) && !(h.hull[2].lo() > near.best_q))
                solve_shared_mark(ps, a, b, shared, j, scratch, st, near);
        }
        return;
    }
    const Mark& mark = shared.marks()[k];
    const ProjectedPatch& pp = ps.patches[mark.patch];
    const MarkJacobian& J = shared.jacobian(k);
    ParamBox rest = mark.box;
    // After a ray that missed this mark, the miss proof below (the
    // Hansen-Sengupta step over the box) comes before Newton: the same step
    // on the same box as after it, so the outcome is the same either way (a
    // proved miss leaves no hit to certify), without Newton's wasted run
    // beside the patch. Teapot 640x480 x 16: 852 -> 842 M in paint_pixels.
    bool held = false; // the Hansen-Sengupta step over the box ran and left `rest`
    RaySystem sys(pp, a, b, scratch.sys, scratch.sys_of);
    if (shared.missed(k) && J.regular) {
        if (!may_hold_zero(sys, J, mark.box, rest, st, shared.centre(k))) return;
        held = true;
    }
    ParamBox hb;
    Interval q;
    if (newton_hit(pp, a, b, mark.box, sys, J, hb, q, st, shared.start(k), shared.at_start(k))) {
        ++near.best.candidates;
        ++st.pixel_patch_solves;
        ++st.pixel_newton_certified;
        shared.hit(k, hb.s.mid(), hb.t.mid());
        near.take(mark.patch, hb, q, static_cast<int>(k));
        return;
    }
    // Newton left the box (the ray passes beside this part of the patch):
    // with a regular Jacobian one Hansen-Sengupta step over the box mostly
    // proves the miss, at a tenth of the clip's cost.
    if (J.regular && !held && !may_hold_zero(sys, J, mark.box, rest, st, shared.centre(k))) {
        shared.miss(k);
        return;
    }
    // A Jacobian that is not regular still proves a miss where the step's
    // box is empty (Theorem 6 ii holds for any A enclosing G'), and
    // otherwise leaves the part of the box holding every hit (6 i).
    if (!J.regular && J.preconditioned &&
        !may_hold_zero(sys, J, mark.box, rest, st, shared.centre(k))) {
        shared.miss(k);
        return;
    }
    shared.miss(k); // unless solve_box finds a hit below
    ParamBox box;
    // Where the Hansen-Sengupta step shrank the box well (below a quarter),
    // solve_box starts on its box without the clip of the mark's whole
    // subpatch (teapot 640x480 x 16: paint_pixels 484.7 -> 457.2 M; a
    // tenth: 458.0 M, a half: 466.4 M, always: 514.6 M).
    if (rest.s.width() * rest.t.width() < 0.25 * mark.box.s.width() * mark.box.t.width()) {
        box = rest;
    } else {
        if (!clip_box(shared.coefs(), pp.shape, Interval(a), Interval(b), mark, box)) return;
        box = {intersect(box.s, rest.s), intersect(box.t, rest.t)}; // both hold every hit
    }
    if (box.s.is_empty() || box.t.is_empty()) return;
    const PixelHit before = near.best;
    solve_box(pp, a, b, box, mark.patch, scratch, st, near, &J, shared.start(k));
    if (near.best.patch == mark.patch &&
        (before.patch != mark.patch || before.s != near.best.s || before.t != near.best.t)) {
        shared.hit(k, near.best.s, near.best.t);
        near.best.mark = static_cast<int>(k);
    }
}

// A mark without a subpatch at hand: solve_box on its box.
void solve_mark(const ProjectedScene& ps, double a, double b, const Mark& mark,
                PixelScratch& scratch, RenderStats& st, Nearest& near) {
    solve_box(ps.patches[mark.patch], a, b, mark.box, mark.patch, scratch, st, near);
}

} // namespace

PixelHit solve_pixel(const ProjectedScene& ps, double a, double b, const Mark* marks, size_t n,
                     PixelScratch& scratch, RenderStats& st, SharedMarks* shared) {
    // Nearest first; once a hit is found, marks that lie entirely beyond it are
    // dropped (section 5, remark 2 after Theorem 10). The ray's q is depth Z.
    scratch.sys_of = {};
    Nearest near;
    if (shared) {
        // The marks in the sub-screen's depth order, those the ray may meet:
        // the same sequence as sorting those alone (teapot 640x480 x 16:
        // paint_pixels 449.2 -> 438.7 M instructions, PNG byte-identical).
        // Refines during the walk change only marks already visited (and
        // append halves, which that mark's solve handles).
        for (const auto& [zlo, k] : shared->depth_order()) {
            if (zlo > near.best_q) break;
            if (shared->may_meet_ray(k, a, b))
                solve_shared_mark(ps, a, b, *shared, k, scratch, st, near);
        }
        if (near.best.candidates > 0) ++st.primary_rays;
        return near.best;
    }
    auto& order = scratch.order;
    order.clear();
    for (size_t k = 0; k < n; ++k) order.push_back({marks[k].hull[2].lo(), static_cast<int>(k)});
    if (order.empty()) return near.best;
    std::sort(order.begin(), order.end());
    for (const auto& [zlo, k] : order) {
        if (zlo > near.best_q) break;
        solve_mark(ps, a, b, marks[k], scratch, st, near);
    }
    ++st.primary_rays;
    return near.best;
}

bool newton_corner(const BezierPatch& b, double a, double bb, const ParamBox& box, double& s,
                   double& t) {
    s = box.s.mid();
    t = box.t.mid();
    for (int it = 0; it < 12; ++it) {
        double step = 0;
        if (!newton_step(b, a, bb, s, t, step)) return false;
        if (!box.s.contains(s) || !box.t.contains(t)) return false;
        if (step < 1e-12) return true;
    }
    return false;
}

} // namespace seamless
