// SPDX-License-Identifier: MIT
#include <seamless/tessellate/trimmed/bounds/chord_bound.h>

#include <cmath>

namespace seamless {
namespace {

BSplineSurface extruded(const BSplineCurve& c) {
    BSplineSurface s;
    s.degree_u = c.degree;
    s.degree_v = 1;
    s.size_u = c.size();
    s.size_v = 2;
    s.knots_u = c.knots;
    s.knots_v = {0, 0, 1, 1};
    for (int i = 0; i < c.size(); ++i)
        for (int j = 0; j < 2; ++j) {
            s.points.push_back(c.points[i]);
            if (c.rational()) s.weights.push_back(c.weights[i]);
        }
    return s;
}

} // namespace

ChordBound::ChordBound(const BSplineCurve& c) : surface_(extruded(c)), bound_(surface_) {}

double ChordBound::operator()(double ta, double tb, Vec3 Pa, Vec3 Pb, double cutoff) const {
    // The third corner a millionth of h above the first: its sides add a
    // factor 1 + 1e-12 to h^2 / 4, and the chord is the interpolant along s = 0.
    const double h = std::abs(tb - ta);
    return bound_({UV{ta, 0}, UV{tb, 0}, UV{ta, 1e-6 * h}}, {Pa, Pb, Pa}, cutoff);
}

} // namespace seamless
