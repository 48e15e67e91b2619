// SPDX-License-Identifier: MIT
// The hits of the rays of a certified cluster B (paper section 7, step 7) as
// functions of the screen point (a, b): the camera-space point P and the
// (unnormalised) normal N = P_s x P_t, each as a second-order interval jet
// over B (interval_jet2.h), for step 9's second-order criterion
// (second_order.h).
//
// The parameters. On the homogeneous system G(s, t; a, b) = (X - a Z, Y - b Z)
// = 0 (primary_cluster.h), whose Jacobian A = dG/d(s, t) is regular over the
// cluster (step 7's certificate), the implicit function theorem gives
//   A (s_a, t_a) = (Z, 0),  A (s_b, t_b) = (0, Z),
// and differentiating G(s(a, b), t(a, b); a, b) = 0 once more,
//   A (s_ab, t_ab) = -(G_ss s_a s_b + G_st (s_a t_b + s_b t_a) + G_tt t_a t_b
//                      + G_sa s_b + G_ta t_b + G_sb s_a + G_tb t_a)
// (and ab = aa, bb alike), with G_sa = (-Z_s, 0), G_sb = (0, -Z_s), G_ta =
// (-Z_t, 0), G_tb = (0, -Z_t), G_aa = G_ab = G_bb = 0. Every quantity is
// enclosed over B (A, G's second derivatives with the hull of a and b), and
// A^-1 = adj A / det A holds the inverse of every matrix in A.
//
// The normal: P_s and P_t composed with (s, t) by the chain rule to second
// order (the patch's third derivatives, enclosure.h), crossed as jets.
//
// The point moves along its ray d = (a, b, 1): P = Z d with Z the camera depth.
// P_a is tangent (N . P_a = 0), so Z_a = -Z N_x / (N . d), Z_b = -Z N_y / (N . d)
// (far tighter than P_s s_a + P_t t_a, whose terms cancel), and Z's second
// partials are those formulas' partials, taken as first-order jets
// (interval_jet.h) of Z, N and d; Z_ab comes out of both and is intersected.
#pragma once

#include <seamless/interval/interval_matrix.h>
#include <seamless/render/scene/projection.h>
#include <seamless/render/shading/interval_jet2.h>
#include <seamless/render/shading/shading.h>
#include <seamless/render/subscreen/primary_cluster.h>
#include <seamless/spline/enclosure/enclosure.h>

namespace seamless {

// A certified cluster B (step 7): every ray of B hits patch pp exactly once
// in `box`; sys: B's cluster system (cluster_system(pp.forms, a, b)); e:
// enclose(pp.forms, box).
struct CertifiedCluster {
    const ProjectedPatch& pp;
    const ParamBox& box;
    const PatchEnclosure& e;
    const ClusterSystem& sys;
};

// A: the interval Jacobian of G over c.box for every ray of B; a, b: B's
// screen coordinates (the hull of its pixels' centres). false when A's
// enclosed determinant may vanish.
bool surface_jets(const CertifiedCluster& c, const IMat<2>& A, Interval a, Interval b,
                  V3<IntervalJet2>& P, V3<IntervalJet2>& N);

} // namespace seamless
