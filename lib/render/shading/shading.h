// SPDX-License-Identifier: MIT
// The illumination model of SHADE (paper section 7): ambient + diffuse +
// Blinn-Phong specular per light, RGB, evaluated either at one point (double)
// or over hulls of points and normals (Interval), so that the interval result
// encloses the intensity of every ray of a cluster. Terms whose coefficient is
// zero, and lights that are off, cost nothing.
#pragma once

#include <seamless/interval/interval.h>
#include <seamless/render/scene/scene.h>

#include <array>
#include <cmath>

namespace seamless {

template <class T> struct V3 { T x, y, z; };
template <class T> V3<T> operator-(const V3<T>& a, const V3<T>& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <class T> V3<T> operator+(const V3<T>& a, const V3<T>& b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
template <class T> T dot3(const V3<T>& a, const V3<T>& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <class T> V3<T> scale3(const V3<T>& a, const T& s) {
    return {a.x * s, a.y * s, a.z * s};
}

inline V3<Interval> to_v3i(Vec3 p) {
    return {Interval(p.x), Interval(p.y), Interval(p.z)};
}
inline V3<double> to_v3(Vec3 p) {
    return {p.x, p.y, p.z};
}

// max(0, x), sqrt and x^s for x >= 0, for both number types.
inline double clamp0(double x) {
    return x > 0 ? x : 0.0;
}
inline Interval clamp0(Interval x) {
    return {std::max(0.0, x.lo()), std::max(0.0, x.hi())};
}
inline double clamp01(double x) {
    return x < 0 ? 0.0 : (x > 1 ? 1.0 : x);
}
inline Interval clamp01(Interval x) {
    return {std::clamp(x.lo(), 0.0, 1.0), std::clamp(x.hi(), 0.0, 1.0)};
}
inline double root(double x) {
    return std::sqrt(x);
}
inline Interval root(Interval x) {
    return sqrt(x);
}
inline double power(double x, double s) {
    return std::pow(x, s);
}
// x^s is monotone for x >= 0; std::pow is within 1 ulp in glibc, so two ulps
// outward enclose the true value.
inline Interval power(Interval x, double s) {
    double lo = std::pow(std::max(0.0, x.lo()), s), hi = std::pow(std::max(0.0, x.hi()), s);
    return {std::max(0.0, next_down(next_down(lo))), next_up(next_up(hi))};
}
inline Interval cosine_range(Interval c) {
    return intersect(c, Interval(-1.0, 1.0));
}
inline double cosine_range(double c) {
    return std::clamp(c, -1.0, 1.0);
}
inline bool surely_positive(double x) {
    return x > 0;
}
inline bool surely_positive(Interval x) {
    return x.lo() > 0;
}
inline bool surely_negative(double x) {
    return x < 0;
}
inline bool surely_negative(Interval x) {
    return x.hi() < 0;
}
inline bool possibly_zero_crossing(double) {
    return false;
}
inline bool possibly_zero_crossing(Interval x) {
    return x.lo() <= 0 && x.hi() >= 0;
}
// Anything in [0, 1]: the intensity where the side facing the viewer is undecided.
inline Interval unit_range(Interval) {
    return {0.0, 1.0};
}
// Either of two values (a term that may be cut off somewhere in a cluster).
inline Interval either(Interval a, Interval b) {
    return hull(a, b);
}

// Intensity in [0, 1] per channel at surface point P with (not necessarily unit)
// normal N, seen from `eye`. The normal is turned towards the viewer (open
// surfaces are seen from both sides). For intervals: returns [0, 1] in every
// channel when the side facing the viewer is undecided (a possible silhouette).
// `eye` may be a box (V3<Interval>) when the viewer is itself a cluster of
// points, as for reflected rays seen from the hull of the mirror's points.
// T: double, Interval, IntervalJet or IntervalJet2 (interval_jet.h,
// interval_jet2.h: the intensity with its first, or first and second, partials
// over a cluster, for step 9's second-order criterion, second_order.h);
// every type but double takes outward-rounded products of the constants.
template <class T>
std::array<T, 3> shade(const Scene& scene, const Material& m, const V3<T>& P, V3<T> N,
                       const V3<T>& eye) {
    const T zero(0.0);
    const V3<T> V = eye - P;
    T nv = dot3(N, V);
    std::array<T, 3> I{T(scene.ambient * m.color.x), T(scene.ambient * m.color.y),
                       T(scene.ambient * m.color.z)};
    if constexpr (!std::is_same_v<T, double>) {
        I = {T(Interval(scene.ambient) * Interval(m.color.x)),
             T(Interval(scene.ambient) * Interval(m.color.y)),
             T(Interval(scene.ambient) * Interval(m.color.z))};
        if (possibly_zero_crossing(nv)) return {unit_range(nv), unit_range(nv), unit_range(nv)};
    }
    if (surely_negative(nv)) N = {-N.x, -N.y, -N.z};
    if (m.diffuse == 0 && m.specular == 0) return {clamp01(I[0]), clamp01(I[1]), clamp01(I[2])};
    const T nlen = root(dot3(N, N));
    const T vlen = root(dot3(V, V));
    for (const Light& light : scene.lights) {
        if (!light.on()) continue;
        const V3<T> L = V3<T>{T(light.position.x), T(light.position.y), T(light.position.z)} - P;
        const T llen = root(dot3(L, L));
        const T cos_nl = cosine_range(dot3(N, L) / (nlen * llen));
        const T diff = clamp0(cos_nl);
        T spec = zero;
        if (m.specular != 0) {
            // Blinn-Phong: half vector of the unit light and view directions.
            const V3<T> H = scale3(L, T(1.0) / llen) + scale3(V, T(1.0) / vlen);
            const T hlen = root(dot3(H, H));
            T cos_nh = clamp0(cosine_range(dot3(N, H) / (nlen * hlen)));
            spec = power(cos_nh, m.shininess);
            if constexpr (std::is_same_v<T, double>) {
                if (cos_nl <= 0) spec = 0; // light behind the surface: no highlight
            } else {
                if (cos_nl.hi() <= 0)
                    spec = zero;
                else if (cos_nl.lo() <= 0)
                    spec = either(spec, zero);
            }
        }
        const double lc[3] = {light.color.x, light.color.y, light.color.z};
        const double mc[3] = {m.color.x, m.color.y, m.color.z};
        for (int c = 0; c < 3; ++c) {
            if (lc[c] == 0) continue;
            T term = T(m.diffuse * mc[c]) * diff;
            if constexpr (!std::is_same_v<T, double>)
                term = T(Interval(m.diffuse) * Interval(mc[c])) * diff;
            if (m.specular != 0) term = term + T(m.specular) * spec;
            I[c] = I[c] + T(lc[c]) * term;
        }
    }
    return {clamp01(I[0]), clamp01(I[1]), clamp01(I[2])};
}

// The same from one eye point.
template <class T>
std::array<T, 3> shade(const Scene& scene, const Material& m, const V3<T>& P, V3<T> N, Vec3 eye) {
    return shade<T>(scene, m, P, N, V3<T>{T(eye.x), T(eye.y), T(eye.z)});
}

// Quantised level of an intensity in [0, 1]: round(I (levels - 1)), halves
// away from zero as std::lround, without its library call: v - trunc(v) is
// exact for 0 <= v < 2^31. (NaN still goes to std::lround.)
inline int quantise(double intensity, int levels) {
    const double v = clamp01(intensity) * (levels - 1);
    if (!(v >= 0 && v < 2147483647.0)) return static_cast<int>(std::lround(v));
    const int i = static_cast<int>(v);
    return i + (v - i >= 0.5 ? 1 : 0);
}

} // namespace seamless
