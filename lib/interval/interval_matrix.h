// SPDX-License-Identifier: MIT
// Small interval vectors and matrices (paper section 2: mid, rad, int(A)),
// N = 2 or 3, plus the real midpoint inverse used as the preconditioner
// C ~ mid(A)^-1 of the Hansen-Sengupta operator (Definition 5, remark).
// Fixed size, value types, no allocation.
#pragma once

#include <seamless/interval/interval.h>

#include <array>
#include <cmath>
#include <type_traits>

namespace seamless {

template <int N> using RVec = std::array<double, N>;
// Row-major real N x N matrix: (i, k) at i * N + k.
template <int N> using RMat = std::array<double, N * N>;

template <int N> struct IVec {
    std::array<Interval, N> v{};

    Interval& operator[](int i) { return v[i]; }
    const Interval& operator[](int i) const { return v[i]; }
    // Empty as soon as one component is empty (a box is a product set).
    bool is_empty() const {
        for (const Interval& x : v)
            if (x.is_empty()) return true;
        return false;
    }
    static IVec empty() {
        IVec r;
        r.v.fill(Interval::empty());
        return r;
    }
};

// Row-major interval N x N matrix: A(i, k).
template <int N> struct IMat {
    std::array<Interval, N * N> a{};

    Interval& operator()(int i, int k) { return a[i * N + k]; }
    const Interval& operator()(int i, int k) const { return a[i * N + k]; }
};

template <int N> RVec<N> mid(const IVec<N>& x) {
    RVec<N> r;
    for (int i = 0; i < N; ++i) r[i] = x[i].mid();
    return r;
}
template <int N> RVec<N> rad(const IVec<N>& x) {
    RVec<N> r;
    for (int i = 0; i < N; ++i) r[i] = x[i].rad();
    return r;
}
template <int N> RMat<N> mid(const IMat<N>& A) {
    RMat<N> r;
    for (int i = 0; i < N * N; ++i) r[i] = A.a[i].mid();
    return r;
}
template <int N> RMat<N> rad(const IMat<N>& A) {
    RMat<N> r;
    for (int i = 0; i < N * N; ++i) r[i] = A.a[i].rad();
    return r;
}
// Largest component width, rounded up.
template <int N> double max_width(const IVec<N>& x) {
    double w = 0;
    for (int i = 0; i < N; ++i) w = std::max(w, x[i].width());
    return w;
}

// Point vector as thin intervals.
template <int N> IVec<N> to_ivec(const std::type_identity_t<RVec<N>>& x) {
    IVec<N> r;
    for (int i = 0; i < N; ++i) r[i] = Interval(x[i]);
    return r;
}

template <int N> IVec<N> operator+(const IVec<N>& x, const IVec<N>& y) {
    IVec<N> r;
    for (int i = 0; i < N; ++i) r[i] = x[i] + y[i];
    return r;
}
template <int N> IVec<N> operator-(const IVec<N>& x, const IVec<N>& y) {
    IVec<N> r;
    for (int i = 0; i < N; ++i) r[i] = x[i] - y[i];
    return r;
}
template <int N> IVec<N> operator-(const IVec<N>& x) {
    IVec<N> r;
    for (int i = 0; i < N; ++i) r[i] = -x[i];
    return r;
}
// Real matrix times interval vector, outward rounded: encloses C x~ for all x~ in x.
template <int N> IVec<N> operator*(const RMat<N>& C, const IVec<N>& x) {
    IVec<N> r;
    for (int i = 0; i < N; ++i) {
        Interval s(0.0);
        for (int k = 0; k < N; ++k) s += Interval(C[i * N + k]) * x[k];
        r[i] = s;
    }
    return r;
}
// Interval matrix times interval vector.
template <int N> IVec<N> operator*(const IMat<N>& A, const IVec<N>& x) {
    IVec<N> r;
    for (int i = 0; i < N; ++i) {
        Interval s(0.0);
        for (int k = 0; k < N; ++k) s += A(i, k) * x[k];
        r[i] = s;
    }
    return r;
}
// Real matrix times interval matrix (the preconditioned C A), outward rounded.
template <int N> IMat<N> operator*(const RMat<N>& C, const IMat<N>& A) {
    IMat<N> r;
    for (int i = 0; i < N; ++i)
        for (int j = 0; j < N; ++j) {
            Interval s(0.0);
            for (int k = 0; k < N; ++k) s += Interval(C[i * N + k]) * A(k, j);
            r(i, j) = s;
        }
    return r;
}

template <int N> IVec<N> intersect(const IVec<N>& x, const IVec<N>& y) {
    IVec<N> r;
    for (int i = 0; i < N; ++i) r[i] = intersect(x[i], y[i]);
    return r;
}
template <int N> IVec<N> hull(const IVec<N>& x, const IVec<N>& y) {
    IVec<N> r;
    for (int i = 0; i < N; ++i) r[i] = hull(x[i], y[i]);
    return r;
}
template <int N> bool contains(const IVec<N>& x, const std::type_identity_t<RVec<N>>& p) {
    for (int i = 0; i < N; ++i)
        if (!x[i].contains(p[i])) return false;
    return true;
}
template <int N> bool contains(const IVec<N>& x, const IVec<N>& y) {
    if (y.is_empty()) return true;
    for (int i = 0; i < N; ++i)
        if (!x[i].contains(y[i])) return false;
    return true;
}
// y lies in int(x) in the paper's sense: strictly inside in every thick
// component of x, equal in every thin one (section 2, used by Theorem 6 iii).
template <int N> bool contains_in_interior(const IVec<N>& x, const IVec<N>& y) {
    if (y.is_empty() || x.is_empty()) return false;
    for (int i = 0; i < N; ++i)
        if (!x[i].contains_in_interior(y[i])) return false;
    return true;
}

template <int N> RMat<N> identity_matrix() {
    RMat<N> r{};
    for (int i = 0; i < N; ++i) r[i * N + i] = 1.0;
    return r;
}

// Options of the midpoint inverse.
struct InverseOptions {
    // A pivot below rel_pivot * (largest |entry| of the matrix) counts as zero:
    // the matrix is reported singular. 1e-13 keeps cond(A) below about 1e13, where
    // C A is still close enough to I for Proposition 8 to have a chance.
    double rel_pivot = 1e-13;
};

// Inverse of a real matrix by Gauss-Jordan elimination with partial pivoting in
// plain double arithmetic. C need not be an exact inverse: the Hansen-Sengupta
// operator is valid for any C (Definition 5), an approximate inverse only makes
// C A close to I. Returns false (inv untouched) if a pivot is (nearly) zero or a
// value is not finite.
template <int N> bool invert(const RMat<N>& A, RMat<N>& inv, const InverseOptions& options = {}) {
    double m[N][2 * N];
    double scale = 0;
    for (int i = 0; i < N; ++i)
        for (int k = 0; k < N; ++k) {
            m[i][k] = A[i * N + k];
            m[i][N + k] = i == k ? 1.0 : 0.0;
            if (!std::isfinite(m[i][k])) return false;
            scale = std::max(scale, std::abs(m[i][k]));
        }
    if (!(scale > 0)) return false;
    const double tiny = options.rel_pivot * scale;
    for (int c = 0; c < N; ++c) {
        int piv = c;
        for (int i = c + 1; i < N; ++i)
            if (std::abs(m[i][c]) > std::abs(m[piv][c])) piv = i;
        if (!(std::abs(m[piv][c]) > tiny)) return false;
        if (piv != c)
            for (int k = 0; k < 2 * N; ++k) std::swap(m[c][k], m[piv][k]);
        const double d = 1.0 / m[c][c];
        for (int k = 0; k < 2 * N; ++k) m[c][k] *= d;
        for (int i = 0; i < N; ++i) {
            if (i == c) continue;
            const double f = m[i][c];
            if (f == 0) continue;
            for (int k = 0; k < 2 * N; ++k) m[i][k] -= f * m[c][k];
        }
    }
    for (int i = 0; i < N; ++i)
        for (int k = 0; k < N; ++k) {
            if (!std::isfinite(m[i][N + k])) return false;
            inv[i * N + k] = m[i][N + k];
        }
    return true;
}

} // namespace seamless
