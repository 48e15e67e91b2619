// SPDX-License-Identifier: MIT
// A single ray against a Bezier patch: Hansen-Sengupta iteration with the
// covering method (paper section 5 after Theorem 10, section 7 remark 1).
//
// The ray O + q D is the intersection of two planes e_k . (P - O) = 0 with e_1,
// e_2 orthogonal to D; with P = X / W this is the polynomial system
//   F_k(s, t) = e_k . X(s, t) - (e_k . O) W(s, t) = 0,  k = 1, 2,
// kept in power form. Each box is contracted by H(x, mid x) with A = F'(x)
// (Definition 4), C = mid(A)^-1, until Theorem 6 iii certifies a unique zero
// and the box is narrower than the tolerance, or the box is empty (no zero).
// When a step makes no progress the wider parameter interval is bisected and
// both halves go on a stack (covering method, section 5 remark 2).
#pragma once

#include <seamless/base/vec.h>
#include <seamless/spline/enclosure/enclosure.h>

#include <optional>
#include <vector>

namespace seamless {

struct Ray {
    Vec3 origin;
    Vec3 direction; // need not be unit length; must not be zero
};

struct RayPatchOptions {
    // A hit is final once both its parameter widths are at most this (local
    // parameters, [0,1]); 1e-10 is far below a pixel and above rounding noise.
    double tolerance = 1e-10;
    // Hansen-Sengupta steps on one box before it is bisected anyway.
    int max_iterations = 32;
    // A step "makes progress" if it shrinks the box's larger width below this
    // fraction of the old one; otherwise the box is bisected (covering method).
    double min_contraction = 0.75;
    // Bisection depth (at most kMaxRayPatchDepth); a box this deep is returned unresolved.
    int max_depth = 60;
    // Boxes examined per ray before the rest are returned unresolved.
    int max_boxes = 20000;
};

inline constexpr int kMaxRayPatchDepth = 120;

struct RayPatchHit {
    ParamBox box;        // local (s, t) of the patch
    Interval q;          // ray parameter: the point is O + q D
    bool unique = false; // Theorem 6 iii: exactly one zero of F in box
};

struct RayPatchStats {
    long long iterations = 0; // Hansen-Sengupta steps
    long long boxes = 0;      // boxes taken from the stack
    long long bisections = 0;
    long long unresolved = 0; // boxes given up at tolerance, depth or box limit
};

// All solution boxes of the ray with the patch (certified and unresolved), q
// unrestricted (hits behind the origin included). Appends to `hits`.
void intersect(const PatchForms& patch, const Ray& ray, std::vector<RayPatchHit>& hits,
               const RayPatchOptions& options = {}, RayPatchStats* stats = nullptr);
// The same, restricted to a start box inside [0,1]^2 (e.g. the parameter box a
// cluster step has already narrowed, section 7 INTRACY step 3.2).
void intersect(const PatchForms& patch, const Ray& ray, ParamBox start,
               std::vector<RayPatchHit>& hits, const RayPatchOptions& options = {},
               RayPatchStats* stats = nullptr);
std::vector<RayPatchHit> intersect(const PatchForms& patch, const Ray& ray,
                                   const RayPatchOptions& options = {},
                                   RayPatchStats* stats = nullptr);

// The hit with the smallest q among those with q.hi >= q_min.
std::optional<RayPatchHit> nearest_hit(const std::vector<RayPatchHit>& hits, double q_min = 0.0);
std::optional<RayPatchHit> nearest_hit(const PatchForms& patch, const Ray& ray,
                                       const RayPatchOptions& options = {},
                                       RayPatchStats* stats = nullptr, double q_min = 0.0);

} // namespace seamless
