// SPDX-License-Identifier: MIT
// A B-rep placed into a larger model (a scene's objects, an assembly's
// instances): its items appended with their indices moved past those already
// there, its 3D geometry mapped by an affine transformation. Affine maps act
// on NURBS control points exactly, and pcurves stay as they are: they live in
// the surfaces' (u,v) domains, which a placement does not change.
#pragma once

#include <seamless/model/brep.h>

namespace seamless {

// Row-major 3x4 affine transformation [A | b]: p -> A p + b.
struct AffineMap {
    double m[12] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
    Vec3 operator()(Vec3 p) const {
        return {m[0] * p.x + m[1] * p.y + m[2] * p.z + m[3],
                m[4] * p.x + m[5] * p.y + m[6] * p.z + m[7],
                m[8] * p.x + m[9] * p.y + m[10] * p.z + m[11]};
    }
    // An upper bound of how much A stretches a length, by which tolerances
    // grow: 1 for the identity, s for a rotation scaled by s, else A's
    // Frobenius norm.
    double stretch() const;
};

// Appends `from` to `into`; its faces' surfaces are surface_offset + their
// index (the caller appends the surfaces, mapped by `map`, in the same order).
// A mirroring map (negative determinant) turns each face's `reversed`.
void append_brep(BRep& into, const BRep& from, int surface_offset, const AffineMap& map);

} // namespace seamless
