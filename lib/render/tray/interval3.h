// SPDX-License-Identifier: MIT
// Three-vectors of intervals for the exact predicates of ray_cluster.h and
// blocking_surface.h, evaluated in interval arithmetic.
#pragma once

#include <seamless/base/vec.h>
#include <seamless/interval/interval.h>

#include <array>

namespace seamless::interval3 {

using IV3 = std::array<Interval, 3>;

inline IV3 isub(const IV3& a, const IV3& b) {
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
inline IV3 icross(const IV3& a, const IV3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline Interval idot(const IV3& a, const IV3& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline IV3 iv(Vec3 v) {
    return {Interval(v.x), Interval(v.y), Interval(v.z)};
}

} // namespace seamless::interval3
