// SPDX-License-Identifier: MIT
// Single primary rays against marked patches: INTRACY step 6 (a one-pixel
// sub-screen, remark 1: the nearest intersection) and the corner rays of step
// 9 (remark 2).
//
// A ray first tries Newton's method in doubles, certified afterwards: when the
// interval Jacobian A of G = (X - aZ, Y - bZ) over the whole box satisfies
// ||I - C A|| < 1 (C = mid(A)^-1), every matrix of A is regular and G is
// one-to-one on the box (G(x) - G(y) = J (x - y) with J in A, row by row by the
// mean value theorem), so the ray meets the patch at most once there;
// Krawczyk's test on a small box around Newton's result (epsilon inflation, as
// kv's kraw-approx; in doubles with a bounded slack, krawczyk_hit), or where
// it fails one Hansen-Sengupta step (Theorem 6 iii), then proves that it meets
// it once, inside the test's box. Without such a proof one Hansen-Sengupta step
// over the whole box either proves a miss (Theorem 6 ii) or contracts the box
// to where the hits may be (Theorem 6 i); that part is tried again, halved
// when it did not shrink much, and only boxes still undecided after a few
// rounds take the full covering method of ray_patch.h. The pixels of a small
// sub-screen (SharedMarks) share A per mark (enclosed for all of their rays),
// computed when the first of them needs it; Newton runs on the mark's whole
// box from the (s, t) where the previous pixel hit the same mark, and only
// where that certifies no hit does the ray clip the mark's subpatch (a
// certain miss, or a smaller box for the steps above).
#pragma once

#include <seamless/render/mark.h>
#include <seamless/render/primary_cluster.h>
#include <seamless/render/projection.h>
#include <seamless/render/render.h>

#include <seamless/interval/hansen_sengupta.h>

#include <array>
#include <limits>
#include <utility>
#include <vector>

namespace seamless {

struct PixelHit {
    int patch = -1; // -1: the ray certainly misses every marked patch
    double s = 0, t = 0, q = 0;
    int candidates = 0; // marks the ray was not excluded from by hull or clip
    int mark = -1;      // with SharedMarks: the mark hit (its index there)
};

// Scratch space reused from ray to ray (nothing allocated per ray once grown).
// Whose power forms a ClusterSystem holds (RaySystem::forms): the patch and
// the ray, or none.
struct FormsKey {
    const ProjectedPatch* pp = nullptr;
    double a = 0, b = 0;
};

struct PixelScratch {
    ClusterSystem sys;
    // sys's owner while one ray is solved (the marks of one patch, halves of
    // a bisection, share the ray's forms); reset by solve_pixel, since
    // others write sys too.
    FormsKey sys_of;
    std::vector<RayPatchHit> hits;
    std::vector<std::pair<double, int>> order;
    std::vector<std::pair<ParamBox, int>> boxes; // boxes still to solve, with their depth
};

// The system G = (X - aZ, Y - bZ) of one ray: point values from the patch's
// power forms directly (X, Y and Z at the point), the power forms of G and its
// derivatives (cluster_system) only when a Jacobian over a box is needed, into
// caller-owned storage (nothing zeroed or allocated per ray).
class RaySystem {
  public:
    RaySystem(const ProjectedPatch& pp, double a, double b, ClusterSystem& storage)
        : pp_(pp), a_(a), b_(b), sys_(storage) {}
    // With storage's owner: forms already built there for this patch and ray are reused.
    RaySystem(const ProjectedPatch& pp, double a, double b, ClusterSystem& storage, FormsKey& of)
        : pp_(pp), a_(a), b_(b), sys_(storage), of_(&of),
          built_(of.pp == &pp && of.a == a && of.b == b) {}
    // G at (s, t) in [0,1]^2, enclosed (enclose_homogeneous of bezier_patch.h).
    IVec<2> at(double s, double t) const;
    // G from X, Y, Z enclosed at a point (X[0..2]; one point for many rays).
    IVec<2> at(const Interval* X) const;
    // The power forms of G, G_s, G_t, built on the first call.
    const ClusterSystem& forms();

  private:
    const ProjectedPatch& pp_;
    double a_, b_;
    ClusterSystem& sys_;
    FormsKey* of_ = nullptr;
    bool built_ = false;
};

// The interval Jacobian A of G over a mark's box, and whether it is regular
// (||I - C A|| < 1). Computed from the cluster system of a sub-screen [a] x [b]
// it encloses G' for every ray of the sub-screen (Definition 4), so the pixels
// of a small sub-screen share one per mark.
struct MarkJacobian {
    IMat<2> A;
    bool regular = false;
    // The Hansen-Sengupta preconditioner, once for every step with A:
    // C = mid(A)^-1 (identity when mid(A) is singular: preconditioned false), CA = C A.
    RMat<2> C{};
    IMat<2> CA;
    bool preconditioned = false;
    // E(i, k) >= |delta_ik - (C A)_ik| for every entry of C A (rounded up):
    // the magnitudes of I - C A for the Krawczyk test of krawczyk_hit.
    RMat<2> E{};
    HansenSenguptaStep<2> step(const IVec<2>& f_center, const IVec<2>& x, const RVec<2>& c) const {
        return hansen_sengupta_preconditioned<2>(C, CA, preconditioned, f_center, x, c);
    }
};
MarkJacobian mark_jacobian(const ClusterSystem& sys, const ParamBox& box);
// The same from a Jacobian enclosed otherwise (subpatch_jacobian of primary_cluster.h).
MarkJacobian mark_jacobian(const IMat<2>& A);

// Krawczyk's test on a small box Y about a point c of Y with J regular over a
// box holding Y: K = c - C G(c) + (I - C A)(Y - c), with |I - C A| bounded by
// J.E. K inside int(Y) proves exactly one zero of G in Y (and it lies in K):
// y - C G(y) maps Y into K, so it has a fixed point there (Brouwer), a zero as
// C is regular. Gc: G(c), enclosed. true with the zero's box (K, within Y) in
// hit; false when K is not inside int(Y) (the Hansen-Sengupta step may still
// succeed: it divides by the diagonal, Krawczyk only bounds by magnitudes).
bool krawczyk_hit(const MarkJacobian& J, const IVec<2>& Gc, const IVec<2>& Y, const RVec<2>& c,
                  ParamBox& hit);

// The certified Newton solve above for the ray through screen point (a, b) and
// patch pp in `box`; sys: the ray's system (RaySystem(pp, a, b, ...)). hit: exactly one hit
// in box, in `hit` (local (s, t)), at depth `q` (camera z, enclosed); miss: certainly none in box
// (a Hansen-Sengupta step over the box is empty, Theorem 6 ii); undecided: take the covering
// method. J: the Jacobian over box for a sub-screen holding the ray (computed here when null).
// rest: when undecided, the part of box that may hold hits (Theorem 6 i). start: where
// Newton starts (clamped into box; null: box's centre).
enum class NewtonOutcome { hit, miss, undecided };
// The hit part alone: true (with hit and q as above) when J is regular and
// Newton's result is certified; false leaves the ray undecided in box.
// at_start: evaluate(pp.patch, start) when known (the first step then evaluates nothing).
bool newton_hit(const ProjectedPatch& pp, double a, double b, const ParamBox& box, RaySystem& sys,
                const MarkJacobian& J, ParamBox& hit, Interval& q, RenderStats& st,
                const double* start = nullptr, const SurfacePoint* at_start = nullptr);
// The part after Newton: false when one Hansen-Sengupta step with J over box
// proves that the ray meets the patch nowhere in box (Theorem 6 ii); else
// rest receives the part of box holding every hit (Theorem 6 i). Xc: X, Y, Z
// at box's centre, enclosed, when known (SharedMarks::centre); else computed.
bool may_hold_zero(const RaySystem& sys, const MarkJacobian& J, const ParamBox& box, ParamBox& rest,
                   RenderStats& st, const Interval* Xc = nullptr);
NewtonOutcome newton_certified(const ProjectedPatch& pp, double a, double b, const ParamBox& box,
                               RaySystem& sys, ParamBox& hit, Interval& q, RenderStats& st,
                               const MarkJacobian* J = nullptr, ParamBox* rest = nullptr,
                               const double* start = nullptr);

// The marks of a small sub-screen [a] x [b] as its pixels share them (INTRACY
// step 6 for every pixel of a B of at most RenderOptions::pixel_subscreen
// pixels): per mark, the Jacobian of G over its box for every ray of B
// (subpatch_jacobian of primary_cluster.h, computed on first need) and the
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
    bool may_meet_ray(size_t k, double a, double b) const {
        const std::array<double, 4>& r = screen_[k];
        if (r[0] == kGeneral) return may_meet(marks_[k], Interval(a), Interval(b));
        return r[0] <= a && a <= r[1] && r[2] <= b && b <= r[3];
    }
    const SubpatchArena& coefs() const { return *coefs_; }
    size_t size() const { return marks_.size(); }
    const MarkJacobian& jacobian(size_t k);
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
    // neighbour likely misses too: the next ray tries the miss proof first;
    // the clip first instead paid less than it cost, 842 -> 853 M on the teapot).
    bool missed(size_t k) const { return missed_[k] != 0; }
    void miss(size_t k) { missed_[k] = 1; }
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
    static constexpr double kGeneral = -std::numeric_limits<double>::infinity();
    static std::array<double, 4> screen(const Mark& m);
};

// Step 6 with remark 1: the nearest intersection of the ray through (a, b)
// with the marked patches, nearest marks first; marks beyond a found hit are
// dropped (section 5, remark 2 after Theorem 10). shared: when given, the
// marks are a small sub-screen's (marks and n are ignored): each is compared
// with the ray by hull, then solved as the comment at the top says.
PixelHit solve_pixel(const ProjectedScene& ps, double a, double b, const Mark* marks, size_t n,
                     PixelScratch& scratch, RenderStats& st, SharedMarks* shared = nullptr);

// A corner ray of a certified cluster hits the patch exactly once in `box`;
// its intensity only steers the bilinear form of step 9, whose levels are
// clamped to the certified enclosure, so plain Newton in doubles suffices.
// false when it does not converge inside the box.
// One Newton step for X - aZ = 0, Y - bZ = 0 from (s, t) in doubles, sp: the
// patch evaluated at (s, t); step: |ds| + |dt|. false where the Jacobian is singular.
bool newton_step(const SurfacePoint& sp, double a, double b, double& s, double& t, double& step);

bool newton_corner(const BezierPatch& b, double a, double bb, const ParamBox& box, double& s,
                   double& t);

} // namespace seamless
