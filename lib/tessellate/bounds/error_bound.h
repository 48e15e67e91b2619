// SPDX-License-Identifier: MIT
// Certified bound on the two-way (Hausdorff) distance between a subpatch and
// its fan triangles (paper section 6; section 5 on the accuracy lost to
// triangles). The bound is geometric, not parametric: the tangential drift of
// the parametrisation, which |S(s,t) - F(s,t)| counts in full, is matched away.
//
// Construction. Let Q = [0,1]^2 be the subpatch's local parameters, S the
// subpatch and F the piecewise linear map of Q onto the fan: the centre
// (1/2,1/2) to the centre vertex, the corners to the corner vertices, linear on
// the four parameter triangles (centre, corner k, corner k+1). For any
// continuous phi: Q -> Q that maps each side of Q into itself with the
// corners fixed, phi is onto (its boundary map has degree 1), so
//   H(S(Q), F(Q)) <= sup_w |S(phi(w)) - F(w)|
// both ways: every S(u) is S(phi(w)) for some w, beside F(w), and every F(w)
// is beside S(phi(w)). phi is piecewise linear on an m x m refinement of each
// fan triangle; its value at each refined vertex w_i is (one Gauss-Newton step
// toward) the foot of F(w_i) on S, so g_i = S(phi(w_i)) - F(w_i) is nearly
// normal and as small as the geometric distance there. On a refined triangle
// sigma, F is linear and S o phi differs from its linear interpolant by at most
//   R = (A ds^2 + 2 B ds dt + C dt^2) / 8
// (Taylor at each vertex; ds, dt the extents of phi(sigma); A, B, C bounds on
// |S_ss|, |S_st|, |S_tt| over Q from the differenced control net, with the
// quotient rule and the smallest weight for rational patches). Split along the
// fan triangle's unit normal n (any unit vector keeps this valid):
//   |g| <= sqrt((max |n.g_i| + R_n)^2 + (max |g_i - (n.g_i) n| + R_t)^2)
// with R_n and R_t the same remainder of the scalar n.S and of the tangential
// part S - (n.S) n (both linear images of S, so their differenced nets bound
// their second derivatives; where the surface curves, S_ss is mostly normal
// and R_t far below R). The tangential remainder falls like 1/m^2, so m is
// chosen to keep it a fraction of the normal part.
#pragma once

#include <seamless/spline/bezier_patch.h>
#include <seamless/tessellate/bounds/power_basis.h>
#include <seamless/tessellate/subdivision/subdivision.h>

#include <array>
#include <span>

namespace seamless {

// Refinements m of each fan triangle are at most this.
inline constexpr int kMaxFanRefinement = 8;

// Bound on the two-way distance between subpatch `b` (its local [0,1]^2) and
// the four triangles (centre, V[k], V[k+1]), V in the order of
// BezierPatch::corner. `target` > 0: a requested tolerance, used only to choose
// m. Without the rounding allowance (rounding_allowance below).
double fan_bound(const BezierPatch& b, Vec3 centre, const std::array<Vec3, 4>& V,
                 double target = 0);
// The same with b's power basis at hand (power_basis.h; has_power_basis(b)).
double fan_bound(const BezierPatch& b, const PowerBasisPatch& pb, Vec3 centre,
                 const std::array<Vec3, 4>& V, double target = 0);

// A vertex of a subpatch's ring: grid point on its patch and position.
struct RingPoint {
    int s = 0, t = 0; // grid point; -1 along a side for another patch's seam vertex
    Vec3 position;
    // Parameters when not a grid point (a seam vertex, edge_graph.h: it lies on
    // a side of this patch, at its projected parameter); < 0: param_of(s, t).
    double fs = -1, ft = -1;
};

// The certified bound of a subpatch's final fan from `centre` over `ring`
// (counterclockwise from the rectangle's corner (s0, t0), with every vertex the
// neighbours put on a side, on straight edges or not). The construction above,
// with phi continuous over the whole Bezier patch instead of one subpatch:
// phi at a vertex or side point shared with a neighbouring fan depends on that
// point alone, and only the patch's own sides must map into themselves, so
// phi may slide a vertex a neighbour moved onto its straight edge toward its
// foot. Hence with B_f this bound for every fan f of a patch, the patch and
// its triangles are within max_f B_f of each other both ways; each point of
// this fan's triangles is within this bound of the patch. Each side shared
// with another fan is cut into 4 pieces (phi linear between), m = 4 to 16;
// derivative bounds over the parameter box of phi's refined vertices (phi is
// linear on each refined triangle, so phi(sigma) lies in it: the subpatch and
// the feet's small moves, as tight as the four-triangle bound's own net).
// Includes the rounding allowance and, for a polynomial bicubic patch, the
// power-basis evaluator's proven rounding (power_basis.h). `target` > 0 (a
// requested tolerance): a bound at or below it is enough, so the coarsest
// refinement (m = 4) is tried first and the finer one only when it ends above
// `target`; `refine` false: not even then (a trial whose failure is cheap).
double certified_fan_bound(const BezierPatch& patch, const ParamRect& r, int depth, Vec3 centre,
                           std::span<const RingPoint> ring, double scale, double target = 0,
                           bool refine = true);

// Bounds on |S_ss| and |S_tt| over the local [0,1]^2 of `b` (the differenced
// control net, quotient rule for rational patches): the remainders a halving
// in s or in t divides by four. The tolerance criterion splits the direction
// with the larger one, so a direction that is straight but unevenly
// parametrised (a cylinder's ruling) is split too.
std::array<double, 2> second_derivative_bounds(const BezierPatch& b);

// Allowance for rounding in de Casteljau (depth halvings), evaluation and the
// bound's own arithmetic at the coordinates' magnitude `scale`: a few ulps per
// operation.
double rounding_allowance(int depth, double scale);

// The subpatch of `patch` over the dyadic rectangle r, or over the box
// [s0, s1] x [t0, t1] of its local parameters, by de Casteljau.
BezierPatch extract_subpatch(const BezierPatch& patch, const ParamRect& r);
BezierPatch extract_box(const BezierPatch& patch, double s0, double s1, double t0, double t1);

} // namespace seamless
