// SPDX-License-Identifier: MIT
// The interval Gauss-Seidel operator Gamma(A, b, x) of Definition 5:
//   y_i = { (b_i - sum_{k<i} A_ik y_k - sum_{k>i} A_ik x_k) / A_ii } intersected with x_i,
// where the division is the extended one (divide_intersect) so that A_ii may
// contain 0. Gamma encloses every solution in x of A~ y = b~ (A~ in A, b~ in b).
#pragma once

#include <seamless/interval/interval.h>
#include <seamless/interval/interval_matrix.h>

namespace seamless {

// Gamma(A, b, x); the whole box is empty as soon as one component is.
template <int N> IVec<N> gauss_seidel(const IMat<N>& A, const IVec<N>& b, const IVec<N>& x) {
    if (x.is_empty() || b.is_empty()) return IVec<N>::empty();
    IVec<N> y = x; // y_k for k < i already updated, x_k for k > i still the old ones
    for (int i = 0; i < N; ++i) {
        Interval num = b[i];
        for (int k = 0; k < N; ++k)
            if (k != i) num -= A(i, k) * y[k];
        // Section 2 remark 1: A_ii may contain 0; the extended division then
        // gives up to two pieces of x_i, of which we keep the hull.
        y[i] = divide_intersect(num, A(i, i), x[i]);
        if (y[i].is_empty()) return IVec<N>::empty();
    }
    return y;
}

} // namespace seamless
