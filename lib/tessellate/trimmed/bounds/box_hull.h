// SPDX-License-Identifier: MIT
// A cheaper bound for one piece of a triangle (triangle_bound.h), from the
// first stage of its restriction alone: the patch over the piece's local
// (s, t) bounding box (triangle_restriction.h, BoxNet) against M, the
// piece's affine map onto the mesh continued over the box, by the hull of
// the tensor-product coefficients of E = X - W M and W (as bilinear_box.cpp,
// in doubles), plus how far M strays from the piece's mesh values. Looser
// than the piece's own hull (the box is about twice the piece, and M is
// continued over it): TriangleBound takes it only where it is already at
// most the cutoff, to skip the triangle's coefficients.
#pragma once

#include <seamless/base/vec.h>
#include <seamless/spline/enclosure/triangle_restriction.h>

#include <array>

namespace seamless {

// A bound of |S(y) - L(y)| over the piece (L: the affine map with the
// values L[k] at the corners box.s[k], box.t[k]); +infinity where the
// corners span no area or a weight is not positive.
double box_hull_bound(const BoxNet& box, const std::array<Vec3, 3>& L);

} // namespace seamless
