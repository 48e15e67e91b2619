// SPDX-License-Identifier: MIT
// Small value types: 3-vectors, homogeneous points and axis-aligned boxes.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace seamless {

struct Vec3 {
    double x = 0, y = 0, z = 0;

    constexpr double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
    constexpr double& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
    friend constexpr Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
    friend constexpr Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
    friend constexpr Vec3 operator-(Vec3 a) { return {-a.x, -a.y, -a.z}; }
    friend constexpr Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
    friend constexpr Vec3 operator*(Vec3 a, double s) { return s * a; }
    friend constexpr Vec3 operator/(Vec3 a, double s) { return {a.x / s, a.y / s, a.z / s}; }
    Vec3& operator+=(Vec3 b) { return *this = *this + b; }
    Vec3& operator-=(Vec3 b) { return *this = *this - b; }
    friend constexpr bool operator==(Vec3 a, Vec3 b) = default;
};

constexpr double dot(Vec3 a, Vec3 b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
constexpr Vec3 cross(Vec3 a, Vec3 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double norm(Vec3 a) {
    return std::sqrt(dot(a, a));
}
inline Vec3 normalize(Vec3 a) {
    double n = norm(a);
    return n > 0 ? a / n : Vec3{};
}
inline double distance(Vec3 a, Vec3 b) {
    return norm(a - b);
}
inline bool is_finite(Vec3 a) {
    return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
}

// Homogeneous point (w*x, w*y, w*z, w) of a rational surface; w = 1 when polynomial.
// De Casteljau and knot insertion act linearly on these four coordinates.
struct HPoint {
    double x = 0, y = 0, z = 0, w = 1;

    static constexpr HPoint from(Vec3 p, double w) { return {w * p.x, w * p.y, w * p.z, w}; }
    constexpr Vec3 xyz() const { return {x, y, z}; }
    constexpr Vec3 point() const { return {x / w, y / w, z / w}; }
    constexpr double operator[](int i) const { return i == 0 ? x : i == 1 ? y : i == 2 ? z : w; }
    constexpr double& operator[](int i) { return i == 0 ? x : i == 1 ? y : i == 2 ? z : w; }
    friend constexpr HPoint operator+(HPoint a, HPoint b) {
        return {a.x + b.x, a.y + b.y, a.z + b.z, a.w + b.w};
    }
    friend constexpr HPoint operator-(HPoint a, HPoint b) {
        return {a.x - b.x, a.y - b.y, a.z - b.z, a.w - b.w};
    }
    friend constexpr HPoint operator*(double s, HPoint a) {
        return {s * a.x, s * a.y, s * a.z, s * a.w};
    }
};

// Affine combination (1-t)*a + t*b, the step of de Casteljau and of Boehm's insertion.
constexpr HPoint lerp(HPoint a, HPoint b, double t) {
    return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.z + t * (b.z - a.z),
            a.w + t * (b.w - a.w)};
}
constexpr Vec3 lerp(Vec3 a, Vec3 b, double t) {
    return a + t * (b - a);
}

// Axis-aligned box; empty when lo > hi in some coordinate (the default).
struct Box3 {
    Vec3 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
            std::numeric_limits<double>::infinity()};
    Vec3 hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
            -std::numeric_limits<double>::infinity()};

    bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
    void extend(Vec3 p) {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
    void extend(const Box3& b) {
        if (b.empty()) return;
        extend(b.lo);
        extend(b.hi);
    }
    Vec3 extent() const { return empty() ? Vec3{} : hi - lo; }
    // Largest extent: the paper's d_max when the box holds every control point (section 8).
    double max_extent() const {
        Vec3 e = extent();
        return std::max({e.x, e.y, e.z});
    }
    bool contains(Vec3 p) const {
        return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z &&
               p.z <= hi.z;
    }
    bool overlaps(const Box3& b) const {
        return lo.x <= b.hi.x && b.lo.x <= hi.x && lo.y <= b.hi.y && b.lo.y <= hi.y &&
               lo.z <= b.hi.z && b.lo.z <= hi.z;
    }
};

} // namespace seamless
