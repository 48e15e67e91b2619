// SPDX-License-Identifier: MIT
#include <seamless/render/subscreen/shared_marks.h>

#include <seamless/render/subscreen/bezier_clip.h>

#include <seamless/render/subscreen/primary_cluster.h>

#include <algorithm>
#include <cmath>

namespace seamless {

void SharedMarks::reset(const ProjectedScene& ps, SubpatchArena& coefs, const Mark* marks, size_t n,
                        Interval a, Interval b, long long family) {
    // Siblings share their parent's marks: the same list (a guard against a
    // family id reused for other marks).
    const bool sibling =
        family >= 0 && family == family_ && marks == family_marks_ && n == family_n_;
    family_marks_ = marks;
    family_n_ = n;
    if (!sibling) {
        bisections_.clear();
        family_coefs_.clear();
        copied_ = 0;
    }
    family_ = family;
    root_.resize(n);
    for (size_t k = 0; k < n; ++k) root_[k] = static_cast<int>(k);
    ps_ = &ps;
    coefs_ = &coefs;
    marks_.assign(marks, marks + n);
    screen_.resize(n);
    for (size_t k = 0; k < n; ++k) screen_[k] = screen(marks[k]);
    diagonal_.assign(n, kUnbounded);
    diagonal_known_.assign(n, 0);
    a_ = a;
    b_ = b;
    jacobians_.resize(n);
    start_.resize(n);
    at_.resize(n);
    known_.assign(n, 0);
    started_.assign(n, 0);
    evaluated_.assign(n, 0);
    depth_.assign(n, 0);
    centre_.resize(n);
    centred_.assign(n, 0);
    missed_.assign(n, 0);
    reorder_ = true;
}

const std::vector<std::pair<double, int>>& SharedMarks::depth_order() {
    if (reorder_) {
        order_.clear();
        for (size_t k = 0; k < marks_.size(); ++k)
            order_.push_back({marks_[k].hull[2].lo(), static_cast<int>(k)});
        std::sort(order_.begin(), order_.end());
        reorder_ = false;
    }
    return order_;
}

std::array<double, 4> SharedMarks::screen(const Mark& m) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    if (!(m.hull[2].hi() > 0)) return {inf, -inf, inf, -inf}; // behind the eye: met by no ray
    if (!(m.pa.is_finite() && m.pb.is_finite())) return {kGeneral, 0, 0, 0};
    return {m.pa.lo(), m.pa.hi(), m.pb.lo(), m.pb.hi()};
}

std::array<double, 4> SharedMarks::diagonals(const Mark& m) const {
    // A point of the subpatch is a convex combination of its control points
    // (wx, wy, wz), so where every wz > 0 its (x + y) / z is a mean of their
    // (wx + wy) / wz, weighted by beta_i wz_i > 0, and likewise x - y. Each
    // quotient's bound is taken with the end of wz that makes it extreme (the
    // sign of fl(x + y) is that of x + y); fl(fl(x + y) / z) is within a
    // relative 2u + u^2 of (x + y) / z (u = 2^-53; 1e-300 for underflow), so
    // the extremes widen by a relative 4.5e-16 and one ulp, and one more ulp
    // for the rounding of a + b and a - b in may_meet_ray (fl(v) <
    // next_down(d) when v < d - ulp, as next_up(fl(v)) >= v).
    const SubpatchShape sh = ps_->patches[m.patch].shape;
    const Interval* c = &(*coefs_)[m.coef];
    constexpr double inf = std::numeric_limits<double>::infinity();
    double lo[2] = {inf, inf}, hi[2] = {-inf, -inf};
    for (int i = 0; i <= sh.p; ++i)
        for (int j = 0; j <= sh.q; ++j) {
            const Interval x = c[sh.index(0, i, j)], y = c[sh.index(1, i, j)];
            const Interval z = c[sh.index(2, i, j)];
            if (!(z.lo() > 0)) return kUnbounded;
            const double nlo[2] = {x.lo() + y.lo(), x.lo() - y.hi()};
            const double nhi[2] = {x.hi() + y.hi(), x.hi() - y.lo()};
            for (int d = 0; d < 2; ++d) {
                lo[d] = std::min(lo[d], nlo[d] / (nlo[d] >= 0 ? z.hi() : z.lo()));
                hi[d] = std::max(hi[d], nhi[d] / (nhi[d] >= 0 ? z.lo() : z.hi()));
            }
        }
    std::array<double, 4> r;
    for (int d = 0; d < 2; ++d) {
        const double slo = 4.5e-16 * std::abs(lo[d]) + 1e-300;
        const double shi = 4.5e-16 * std::abs(hi[d]) + 1e-300;
        r[2 * d] = next_down(next_down(lo[d] - slo));
        r[2 * d + 1] = next_up(next_up(hi[d] + shi));
    }
    for (const double v : r)
        if (!std::isfinite(v)) return kUnbounded;
    return r;
}

const Interval* SharedMarks::centre(size_t k) {
    if (!centred_[k]) {
        const Mark& m = marks_[k];
        const RVec<2> c = mid(IVec<2>{{m.box.s, m.box.t}}); // may_hold_zero's centre
        enclose_homogeneous(ps_->patches[m.patch].patch, c[0], c[1], 3, centre_[k].data());
        centred_[k] = 1;
    }
    return centre_[k].data();
}

const MarkJacobian& SharedMarks::jacobian(size_t k) {
    if (!known_[k]) {
        // From the mark's subpatch: a hull of coefficient differences instead
        // of four power-form ranges.
        const Mark& m = marks_[k];
        jacobians_[k] = mark_jacobian(
            subpatch_jacobian(&(*coefs_)[m.coef], ps_->patches[m.patch].shape, m.box, a_, b_));
        known_[k] = 1;
    }
    return jacobians_[k];
}

bool SharedMarks::refine(size_t k) {
    if (jacobian(k).regular || depth_[k] >= kMaxDepth) return false;
    const Mark m = marks_[k];
    const int dir = m.box.s.width() >= m.box.t.width() ? 0 : 1;
    if (!((dir == 0 ? m.box.s : m.box.t).width() > 1e-9)) return false;
    Mark half[2];
    bisect(k, half);
    marks_[k] = half[0];
    marks_.push_back(half[1]);
    screen_[k] = screen(half[0]);
    screen_.push_back(screen(half[1]));
    diagonal_[k] = kUnbounded; // the halves' own on their first miss
    diagonal_.push_back(kUnbounded);
    diagonal_known_[k] = 0;
    diagonal_known_.push_back(0);
    known_[k] = 0;
    known_.push_back(0);
    centred_[k] = 0;
    centred_.push_back(0);
    centre_.emplace_back();
    jacobians_.emplace_back();
    start_.push_back(start_[k]);
    started_.push_back(started_[k]);
    at_.push_back(at_[k]);
    evaluated_.push_back(evaluated_[k]);
    missed_.push_back(missed_[k]);
    depth_[k] = static_cast<char>(depth_[k] + 1);
    depth_.push_back(depth_[k]);
    root_.push_back(root_[k]);
    reorder_ = true;
    return true;
}

void SharedMarks::bisect(size_t k, Mark half[2]) {
    const Mark& m = marks_[k];
    const SubpatchShape sh = ps_->patches[m.patch].shape;
    const size_t size = sh.size();
    SubpatchArena& coefs = *coefs_;
    // A sibling of B bisected the same mark: its halves, subpatches copied.
    // The marks of a family are equal up to their subpatches' offsets, so a
    // mark's root and box name it.
    for (const Bisection& e : bisections_) {
        if (e.root != root_[k] || !(e.box.s == m.box.s && e.box.t == m.box.t)) continue;
        for (int i = 0; i < 2; ++i) {
            half[i] = e.half[i];
            half[i].coef = coefs.size();
            coefs.insert(coefs.end(), family_coefs_.begin() + e.coef + i * size,
                         family_coefs_.begin() + e.coef + (i + 1) * size);
        }
        ++copied_;
        return;
    }
    bisect_mark(coefs, sh, m, m.box.s.width() >= m.box.t.width() ? 0 : 1, half);
    for (int i = 0; i < 2; ++i) {
        Mark& h = half[i];
        // The halves' subpatches enclose them (convex hull property); the
        // parent's hull still holds them too.
        update_enclosures(coefs, sh, h);
        for (int c = 0; c < 3; ++c) h.hull[c] = intersect(h.hull[c], m.hull[c]);
    }
    if (family_ < 0) return;
    bisections_.push_back({root_[k], m.box, {half[0], half[1]}, family_coefs_.size()});
    for (int i = 0; i < 2; ++i)
        family_coefs_.insert(family_coefs_.end(), coefs.begin() + half[i].coef,
                             coefs.begin() + half[i].coef + size);
}

} // namespace seamless
