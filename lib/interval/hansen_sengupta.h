// SPDX-License-Identifier: MIT
// The Hansen-Sengupta operator (Definition 5, Theorem 6):
//   H(x, x~) = x~ + Gamma(C A, -C F(x~), x - x~),  C ~ mid(A)^-1,
// where A is a Lipschitz matrix of F on the box x (Definition 4: an interval
// extension of F' over x) and F(x~) is given as an enclosure (it is computed
// with rounding). All arithmetic is outward rounded, so the computed box
// encloses the exact H(x, x~) and Theorem 6 holds for it:
//   (i) every zero of F in x lies in the new box, (ii) empty box: no zero in x,
//   (iii) non-empty box inside int(x): exactly one zero in x.
#pragma once

#include <seamless/base/check.h>
#include <seamless/interval/gauss_seidel.h>
#include <seamless/interval/interval_matrix.h>

#include <type_traits>

namespace seamless {

template <int N> struct HansenSenguptaStep {
    IVec<N> box;                 // H(x, x~) intersected with x; empty: no zero in x (Theorem 6 ii)
    bool unique = false;         // Theorem 6 iii: F has exactly one zero in x (and it lies in box)
    bool preconditioned = false; // mid(A) was invertible; otherwise C = I was used
};

// One step. A: Lipschitz matrix of F over x; f_center: enclosure of F(center);
// center: a point of x (the paper takes x~ = mid(x), Theorem 7).
// The step with the preconditioner given: C (any real matrix; preconditioned:
// whether it is mid(A)^-1) and CA = C * A, for many steps with one A (a
// Jacobian shared by the rays of a sub-screen).
template <int N>
HansenSenguptaStep<N> hansen_sengupta_preconditioned(const RMat<N>& C, const IMat<N>& CA,
                                                     bool preconditioned, const IVec<N>& f_center,
                                                     const IVec<N>& x,
                                                     const std::type_identity_t<RVec<N>>& center) {
    HansenSenguptaStep<N> r;
    r.preconditioned = preconditioned;
    if (x.is_empty()) {
        r.box = IVec<N>::empty();
        return r;
    }
    SEAMLESS_CHECK(contains(x, center), "the center lies in the box (Theorem 6)");
    const IVec<N> xc = to_ivec<N>(center);
    const IVec<N> g = gauss_seidel(CA, -(C * f_center), x - xc);
    if (g.is_empty()) {
        r.box = IVec<N>::empty();
        return r;
    }
    const IVec<N> h = xc + g;
    // Theorem 6 iii on the enclosure of H (before clipping to x): if it lies in
    // int(x), so does the exact H(x, x~).
    r.unique = contains_in_interior(x, h);
    r.box = intersect(h, x); // every zero of F in x is in both (Theorem 6 i)
    if (r.box.is_empty()) r.unique = false;
    return r;
}

// One step. A: Lipschitz matrix of F over x; f_center: enclosure of F(center);
// center: a point of x (the paper takes x~ = mid(x), Theorem 7).
template <int N>
HansenSenguptaStep<N> hansen_sengupta(const IMat<N>& A, const IVec<N>& f_center, const IVec<N>& x,
                                      const std::type_identity_t<RVec<N>>& center,
                                      const InverseOptions& options = {}) {
    if (x.is_empty()) return hansen_sengupta_preconditioned<N>({}, {}, false, f_center, x, center);
    // Definition 5, remark: for small n take C ~ mid(A)^-1. Any real C keeps
    // Theorem 6 valid, so a singular midpoint falls back to C = I.
    RMat<N> C;
    const bool preconditioned = invert<N>(mid(A), C, options);
    if (!preconditioned) C = identity_matrix<N>();
    return hansen_sengupta_preconditioned<N>(C, C * A, preconditioned, f_center, x, center);
}

} // namespace seamless
