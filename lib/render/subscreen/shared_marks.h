// SPDX-License-Identifier: MIT
#pragma once

#include <seamless/render/pixels/pixel_solve.h>
#include <seamless/render/scene/projection.h>
#include <seamless/render/subscreen/mark.h>

#include <array>
#include <limits>
#include <utility>
#include <vector>

namespace seamless {

// The marks of a small sub-screen [a] x [b] as its pixels share them (INTRACY
// step 6 for every pixel of a B of at most RenderOptions::pixel_subscreen
// pixels): per mark, the Jacobian of G over its box for every ray of B
// (subpatch_jacobian of bezier_clip.h, computed on first need) and the
// (s, t) of the last hit on it, where the next pixel's Newton starts. A mark
// whose Jacobian is not regular (a silhouette may cross its box) is bisected
// for all of B's pixels at once (covering method, section 5 remark 2): the
// halves together hold every hit of the mark, each with its own hull and
// Jacobian, so the rays beside a silhouette are mostly decided by hull or by
// one Newton solve instead of each halving the box for itself.
class SharedMarks {
  public:
    // B's marks (n of them, subpatches in `coefs`), for the rays through [a] x
    // [b]. The halves of bisected marks are appended to `coefs` (the caller
    // truncates it after B). family: B's siblings (the sub-screens split from
    // one parent, sharing its marks and `coefs` up to the end of them) pass
    // the same id, and the bisections one of them made are copied for the
    // next instead of computed again (the same halves, bit for bit); -1: none.
    void reset(const ProjectedScene& ps, SubpatchArena& coefs, const Mark* marks, size_t n,
               Interval a, Interval b, long long family = -1);
    const Mark* marks() const { return marks_.data(); }
    // may_meet(marks()[k], a, b) for the thin ray through (a, b): the mark's
    // screen enclosure as four bounds kept per mark (may_meet's own test
    // where it is not finite).
    // After a ray missed the mark, also by the diagonal bounds (diagonals()).
    bool may_meet_ray(size_t k, double a, double b) const {
        const std::array<double, 4>& r = screen_[k];
        if (r[0] == kGeneral) return may_meet(marks_[k], Interval(a), Interval(b));
        if (!(r[0] <= a && a <= r[1] && r[2] <= b && b <= r[3])) return false;
        // fl(a + b) and fl(a - b) are within half an ulp of the exact values,
        // which diagonal_ allows for (one ulp wider).
        const std::array<double, 4>& d = diagonal_[k];
        const double sum = a + b, diff = a - b;
        return !(sum < d[0] || sum > d[1] || diff < d[2] || diff > d[3]);
    }
    const SubpatchArena& coefs() const { return *coefs_; }
    size_t size() const { return marks_.size(); }
    const MarkJacobian& jacobian(size_t k);
    // Every mark as (its nearest depth hull[2].lo(), index), sorted: the
    // order in which a ray solves the marks it may meet (solve_pixel),
    // sorted once per B and again only after a refine, not per pixel.
    // Marks refined while a ray walks it keep their place until the next ray.
    const std::vector<std::pair<double, int>>& depth_order();
    // Mark k bisected when its Jacobian is not regular: k becomes one half,
    // the new last mark the other. false when k is left as it is (regular,
    // bisected kMaxDepth times already, or its box too small).
    bool refine(size_t k);
    // Where Newton starts on mark k: the last hit on it, or null.
    const double* start(size_t k) const { return started_[k] ? start_[k].data() : nullptr; }
    void hit(size_t k, double s, double t) {
        start_[k] = {s, t};
        started_[k] = 1;
        evaluated_[k] = 0;
        missed_[k] = 0;
    }
    // Whether the last ray solved on mark k certainly missed it (its
    // neighbour likely misses too: the next ray tries the miss proof first,
    // which is cheaper than the clip).
    bool missed(size_t k) const { return missed_[k] != 0; }
    // The first miss on mark k bounds it diagonally too (diagonals(); beside
    // a silhouette its neighbours miss it as well, often outside those bounds).
    void miss(size_t k) {
        if (!missed_[k] && !diagonal_known_[k]) {
            diagonal_[k] = diagonals(marks_[k]);
            diagonal_known_[k] = 1;
        }
        missed_[k] = 1;
    }
    // The patch evaluated at mark k's start (surface_frame's, when the pixel
    // that hit it is shaded), for the next Newton run from there; null when unknown.
    const SurfacePoint* at_start(size_t k) const { return evaluated_[k] ? &at_[k] : nullptr; }
    void evaluated(size_t k, double s, double t, const SurfacePoint& sp) {
        if (!started_[k] || start_[k][0] != s || start_[k][1] != t) return;
        at_[k] = sp;
        evaluated_[k] = 1;
    }
    // X, Y, Z of mark k's patch at its box's centre, enclosed: the same for
    // every ray of B (may_hold_zero's G there), computed on first need.
    const Interval* centre(size_t k);
    static constexpr int kMaxDepth = 3; // bisections of one mark of B
    // Bisections copied from B's siblings since its family began.
    int copied() const { return copied_; }

  private:
    const ProjectedScene* ps_ = nullptr;
    SubpatchArena* coefs_ = nullptr;
    std::vector<Mark> marks_;
    Interval a_, b_;
    std::vector<MarkJacobian> jacobians_;
    std::vector<std::array<double, 2>> start_;
    std::vector<SurfacePoint> at_;
    std::vector<std::array<Interval, 3>> centre_;
    std::vector<char> known_, started_, depth_, evaluated_, centred_, missed_;
    std::vector<std::pair<double, int>> order_; // depth_order(), valid when !reorder_
    bool reorder_ = true;
    // Per mark: the index of the mark of B it was bisected from (itself when not).
    std::vector<int> root_;
    // The bisections made for B's family (reset's family): the halves of the
    // mark of box `box` bisected from root mark `root`, their subpatches at
    // `coef` in family_coefs_ (two of the shape's size), as refine made them.
    struct Bisection {
        int root;
        ParamBox box;
        Mark half[2];
        size_t coef;
    };
    long long family_ = -1;
    const Mark* family_marks_ = nullptr; // the family's marks and their count
    size_t family_n_ = 0;
    int copied_ = 0;
    std::vector<Bisection> bisections_;
    SubpatchArena family_coefs_;
    void bisect(size_t k, Mark half[2]);
    // Per mark: pa and pb's bounds (an empty range behind the eye), or
    // kGeneral in the first where pa or pb is not finite.
    std::vector<std::array<double, 4>> screen_;
    // Per mark: bounds of (x + y) / z and (x - y) / z over it, where a ray
    // (a, b) meets it only with a + b and a - b inside, each one ulp wider;
    // unbounded until the first miss (diagonal_known_).
    std::vector<std::array<double, 4>> diagonal_;
    std::vector<char> diagonal_known_;
    static constexpr double kGeneral = -std::numeric_limits<double>::infinity();
    static constexpr std::array<double, 4> kUnbounded = {
        -std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
        -std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    static std::array<double, 4> screen(const Mark& m);
    std::array<double, 4> diagonals(const Mark& m) const;
};

} // namespace seamless
