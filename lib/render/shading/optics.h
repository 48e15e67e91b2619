// SPDX-License-Identifier: MIT
// Reflected and refracted directions (paper section 7, SHADE steps 3.1 and 4),
// for one ray (T = double: TRAY, INTRACY's single pixels) and for a cluster
// (T = Interval: INTRACY's certified clusters, where the result encloses the
// direction of every ray of the cluster). The interval version answers only
// when the case (which side the rays come from, total internal reflection) is
// the same for every ray; otherwise it returns false and the cluster is split.
#pragma once

#include <seamless/render/shading/shading.h>

#include <cmath>

namespace seamless {

// Reflected directions D - 2 (D.N / N.N) N of incoming directions D at normals
// N (SHADE step 3.1; N need not be unit). false when N.N may vanish.
template <class T> bool reflect_direction(const V3<T>& D, const V3<T>& N, V3<T>& R) {
    const T nn = dot3(N, N);
    if (!surely_positive(nn)) return false;
    const T k = T(2.0) * dot3(D, N) / nn;
    R = D - scale3(N, k);
    return true;
}

// Refracted directions of incoming directions D at normals N (SHADE step 4):
// entering when the ray comes from the side N points to (relative index
// 1 / ior), leaving otherwise (ior); Snell's law; total internal reflection
// gives the reflected direction. For a double a ray grazing the surface
// (cos = 0) counts as leaving. false when a length may vanish or, for a
// cluster, the side or total reflection is undecided.
template <class T> bool refract_direction(const V3<T>& D, const V3<T>& N, double ior, V3<T>& out) {
    using std::abs;
    const T dd = dot3(D, D), nn = dot3(N, N);
    if (!surely_positive(dd) || !surely_positive(nn)) return false;
    const T dl = root(dd), nl = root(nn);
    const V3<T> v{-D.x / dl, -D.y / dl, -D.z / dl}; // unit, towards the viewer
    V3<T> n{N.x / nl, N.y / nl, N.z / nl};          // unit normal
    const T cos_v = dot3(v, n);
    if (possibly_zero_crossing(cos_v)) return false;
    const bool entering = surely_positive(cos_v);
    if (!entering) n = {-n.x, -n.y, -n.z};
    const T cos_i = abs(cos_v);
    const T eta(entering ? 1 / ior : ior);
    const T k = T(1.0) - eta * eta * (T(1.0) - cos_i * cos_i);
    if (possibly_zero_crossing(k)) return false;
    if (surely_negative(k)) return reflect_direction(D, N, out); // total internal reflection
    const T f = eta * cos_i - root(k);
    out = {f * n.x - eta * v.x, f * n.y - eta * v.y, f * n.z - eta * v.z};
    return true;
}

} // namespace seamless
