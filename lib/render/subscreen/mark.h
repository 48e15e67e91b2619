// SPDX-License-Identifier: MIT
// A marked patch of a sub-screen (paper section 7, INTRACY step 3): the patch,
// the parameter box that may still hold hits of the sub-screen's rays, a
// camera-space enclosure of the patch over that box, and the subpatch over the
// box (subpatch.h) that a child sub-screen narrows further instead of starting
// again from the parent's box.
#pragma once

#include <seamless/interval/interval_matrix.h>
#include <seamless/spline/enclosure/enclosure.h>
#include <seamless/spline/enclosure/subpatch.h>

#include <cstddef>
#include <vector>

namespace seamless {

struct Mark {
    int patch;
    ParamBox box;
    IVec3 hull; // camera-space enclosure of the patch over box (or a superset)
    // Offset of the subpatch's coefficients over `box` in the renderer's
    // coefficient arena (shape: the patch's SubpatchShape).
    size_t coef = 0;
    // Screen enclosure (a, b) = (X / Z, Y / Z) of the patch over box; entire
    // when unknown (a control point not in front of the eye).
    Interval pa = Interval::entire(), pb = Interval::entire();
};

// The subpatches of marks live in one flat array, appended to and truncated
// in the order of the sub-screen stack (nothing allocated once it has grown).
using SubpatchArena = std::vector<Interval>;

// The hull comparison of step 3: false when no ray through [a] x [b] can meet
// the patch in m.box (by the screen enclosure where known, else by the hull).
inline bool may_meet(const Mark& m, Interval a, Interval b) {
    const IVec3& P = m.hull;
    if (!(P[2].hi() > 0)) return false; // behind the eye
    if (m.pa.is_finite() && m.pb.is_finite())
        return !intersect(m.pa, a).is_empty() && !intersect(m.pb, b).is_empty();
    return (P[0] - a * P[2]).contains(0.0) && (P[1] - b * P[2]).contains(0.0);
}

// Sets m.hull, m.pa, m.pb from its subpatch (convex hull property).
void update_enclosures(const SubpatchArena& arena, SubpatchShape sh, Mark& m);

// The mark of a whole patch (box [0,1]^2; hull: an enclosure of the whole
// patch), its control points appended to the arena as its subpatch, its
// enclosures from them within `hull`.
Mark whole_patch_mark(int patch, const BezierPatch& b, SubpatchShape sh, const IVec3& hull,
                      SubpatchArena& arena);

// Narrows m for the cluster of primary rays through [a] x [b] (Theorem 10 by
// Bezier clipping on the subpatch, clip_cluster of bezier_clip.h): up to
// three passes, each clipping and restricting the subpatch (appended to the
// arena), while the clip shrinks the box by a fifth (a smaller shrink is not
// restricted: m keeps its box). Returns false when no ray of the
// cluster meets the patch in m.box. D: the derivative ranges of the last clip
// (over a subpatch holding the final box), for the silhouette test.
bool narrow_mark(SubpatchArena& arena, SubpatchShape sh, Interval a, Interval b, Mark& m,
                 IMat<2>* D);

// One Bezier clip of m's subpatch for the rays through [a] x [b] (a single
// ray when thin), without restricting the subpatch: false when no such ray
// meets the patch in m.box, else `box` (within m.box) holds every hit. For a
// pixel's solve: cheaper than a Hansen-Sengupta step, and it decides most
// rays that pass beside a patch's edge.
bool clip_box(const SubpatchArena& arena, SubpatchShape sh, Interval a, Interval b, const Mark& m,
              ParamBox& box);

// m's box halved at the midpoint of direction dir, each half with its own
// subpatch (appended to the arena); enclosures not updated.
void bisect_mark(SubpatchArena& arena, SubpatchShape sh, const Mark& m, int dir, Mark out[2]);

// Remark 3: where a silhouette is possible the patch is separated: when a
// midline of m's box is certainly free of zeros of one equation, the halves on
// either side are narrowed apart. Returns how many marks (0: no ray meets the
// patch in m.box; 1: out[0] = m, unseparated).
int separate_mark(SubpatchArena& arena, SubpatchShape sh, Interval a, Interval b, const Mark& m,
                  Mark out[2]);

// m's subpatch restricted to to ^ m.box into out (sh.size() coefficients):
// false when the two boxes do not meet. got: the box the coefficients belong
// to, which keeps m.box's range along a direction where `to` is too thin to
// restrict to.
bool restrict_mark(const SubpatchArena& arena, SubpatchShape sh, const Mark& m, ParamBox to,
                   Interval* out, ParamBox& got);

// The partial derivatives of the point X / W over a subpatch's box (its
// coefficients c over exactly `box`; point: an enclosure of X / W there): p
// times the hull of the coefficients' s-differences divided by the box's width
// (the derivative of a Bezier patch and the convex hull property), t alike;
// for a rational patch the quotient rule P_s = (X_s - P W_s) / W with W the
// hull of the weights. false where the box is too thin to divide by or a
// weight is not certainly positive.
bool subpatch_derivatives(const Interval* c, SubpatchShape sh, const ParamBox& box,
                          const IVec3& point, IVec3& ds, IVec3& dt);

// The range of n . X over the points X of m's subpatch: the hull of n . P over
// its control points P (convex hull property; the weights must be positive,
// else entire).
Interval plane_range(const SubpatchArena& arena, SubpatchShape sh, const Mark& m, const Vec3& n);

} // namespace seamless
