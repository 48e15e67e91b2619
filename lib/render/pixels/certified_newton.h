// SPDX-License-Identifier: MIT
// Certified Newton for one ray and one patch in a box. A ray first tries Newton's method in
// doubles, certified afterwards: when the interval Jacobian A of G = (X - aZ, Y - bZ) over the
// whole box satisfies
// ||I - C A|| < 1 (C = mid(A)^-1), every matrix of A is regular and G is
// one-to-one on the box (G(x) - G(y) = J (x - y) with J in A, row by row by the
// mean value theorem), so the ray meets the patch at most once there;
// Krawczyk's test on a small box around Newton's result (epsilon inflation, as
// kv's kraw-approx; in doubles with a bounded slack, krawczyk_hit), or where
// it fails one Hansen-Sengupta step (Theorem 6 iii), then proves that it meets
// it once, inside the test's box. Without such a proof one Hansen-Sengupta step
// over the whole box either proves a miss (Theorem 6 ii) or contracts the box
// to where the hits may be (Theorem 6 i).
//
// Single pixels and corner rays (pixel_solve.h) and the pixels of a certified
// cluster (certified_pixels.h) are solved with these.
#pragma once

#include <seamless/render/scene/projection.h>
#include <seamless/render/scene/render_options.h>
#include <seamless/render/scene/render_stats.h>
#include <seamless/render/subscreen/primary_cluster.h>

#include <seamless/interval/hansen_sengupta.h>

#include <limits>

namespace seamless {

// Whose power forms a ClusterSystem holds (RaySystem::forms): the patch and
// the ray, or none.
struct FormsKey {
    const ProjectedPatch* pp = nullptr;
    double a = 0, b = 0;
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
    // The ray's patch and screen point.
    const ProjectedPatch& patch() const { return pp_; }
    double a() const { return a_; }
    double b() const { return b_; }

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
// The same from a Jacobian enclosed otherwise (subpatch_jacobian of bezier_clip.h).
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
// in box, in `hit` (hit.box: local (s, t); hit.q: camera z, enclosed); miss: certainly none in box
// (a Hansen-Sengupta step over the box is empty, Theorem 6 ii); undecided: take the covering
// method. J: the Jacobian over box for a sub-screen holding the ray (computed here when null).
// rest: when undecided, the part of box that may hold hits (Theorem 6 i). start: where
// Newton starts (clamped into box; null: box's centre).
enum class NewtonOutcome { hit, miss, undecided };
struct CertifiedHit {
    ParamBox box; // holds exactly one zero of G
    Interval q;   // camera depth over box
};
// The hit part alone: true (with hit as above) when J is regular and
// Newton's result is certified; false leaves the ray undecided in box.
// start.at: evaluate(pp.patch, start.st) when known (the first step then evaluates nothing).
// frame (optional): Newton's point (s, t) and the patch there (point and
// partial derivatives), from the evaluation that encloses G there for the
// certificate (enclose_homogeneous of bezier_patch.h): for the shading and
// the next run's first step, without evaluating the patch again.
struct NewtonFrame {
    double s = 0, t = 0;
    SurfacePoint at{};
};
struct NewtonStart {
    const double* st = nullptr;       // (s, t); null: the box's centre
    const SurfacePoint* at = nullptr; // the patch evaluated there; null: unknown
};
bool newton_hit(RaySystem& sys, const ParamBox& box, const MarkJacobian& J, CertifiedHit& hit,
                RenderStats& st, NewtonStart start = {}, NewtonFrame* frame = nullptr);
// The part after Newton: false when one Hansen-Sengupta step with J over box
// proves that the ray meets the patch nowhere in box (Theorem 6 ii); else
// rest receives the part of box holding every hit (Theorem 6 i). Xc: X, Y, Z
// at box's centre, enclosed, when known (SharedMarks::centre); else computed.
bool may_hold_zero(const RaySystem& sys, const MarkJacobian& J, const ParamBox& box, ParamBox& rest,
                   RenderStats& st, const Interval* Xc = nullptr);
NewtonOutcome newton_certified(RaySystem& sys, const ParamBox& box, CertifiedHit& hit,
                               RenderStats& st, const MarkJacobian* J = nullptr,
                               ParamBox* rest = nullptr, const double* start = nullptr);

// One Newton step for X - aZ = 0, Y - bZ = 0 from (s, t) in doubles, sp: the
// patch evaluated at (s, t); step: |ds| + |dt|. false where the Jacobian is singular.
bool newton_step(const SurfacePoint& sp, double a, double b, double& s, double& t, double& step);
// The same step on the homogeneous system G = (X - aZ, Y - bZ), the patch
// evaluated at (s, t) inside (fixed-degree kernels for bicubic, biquadratic
// and bilinear patches): the same zeros, fewer operations.
bool ray_newton_step(const BezierPatch& p, double a, double b, double& s, double& t, double& step);

// Newton in doubles for the ray through (a, b) on a patch known to be hit
// exactly once in `box` (a certified cluster's pixels and corner rays): where
// it starts (a hit, with the patch evaluated there) and what its run showed:
// the hit minus the point of Newton's first step (a step from the previous
// pixel's hit is a linear prediction whose error varies smoothly along a row,
// so the next pixel's first point moves by it: an error of third order in the
// pixel spacing instead of second), and the convergence constant k. along:
// the run started from the previous pixel of its row.
struct NewtonRun {
    double s = 0, t = 0;
    SurfacePoint at{};
    double ds = 0, dt = 0;
    double k = std::numeric_limits<double>::infinity();
    bool along = false;
};
// The first step from from.at, then, when along && from.along, from's
// correction added; the rest on the ray's homogeneous system
// (ray_newton_step). Converged: a step below 1e-9 (near the regular zero the
// error is then of its square's order), or a step d <= 1e-5 whose successor,
// by quadratic convergence about k d^2, would be below 1e-12 (k measured on
// this run or, at least 1, on from's). true with the hit in `to` (to.at left
// to the caller) when it converges inside box; false otherwise.
bool newton_in_box(const BezierPatch& patch, double a, double b, const ParamBox& box,
                   const NewtonRun& from, bool along, NewtonRun& to);
// A corner ray's: newton_in_box from box's centre. Its intensity only steers
// the bilinear form of step 9, whose levels are clamped to the certified
// enclosure, so plain Newton in doubles suffices.
bool newton_corner(const BezierPatch& b, double a, double bb, const ParamBox& box, double& s,
                   double& t);

} // namespace seamless
