// SPDX-License-Identifier: MIT
#include <seamless/model/brep_placement.h>

#include <cmath>

namespace seamless {

double AffineMap::stretch() const {
    // A^T A: s^2 I for a rotation scaled by s (CAD placements, to rounding).
    double ata[3][3], frobenius = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            ata[i][j] = m[i] * m[j] + m[4 + i] * m[4 + j] + m[8 + i] * m[8 + j];
    for (int i = 0; i < 3; ++i) frobenius += ata[i][i];
    const double s2 = frobenius / 3;
    bool similarity = true, identity = true;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            similarity = similarity && std::abs(ata[i][j] - (i == j ? s2 : 0)) <= 1e-9 * s2;
            identity = identity && m[4 * i + j] == (i == j ? 1 : 0);
        }
    if (identity) return 1;
    // The rounding's 1e-9 added: still an upper bound.
    return similarity ? std::sqrt(s2) * (1 + 1e-9) : std::sqrt(frobenius);
}

void append_brep(BRep& into, const BRep& from, int surface_offset, const AffineMap& map) {
    const int v0 = static_cast<int>(into.vertices.size());
    const int c0 = static_cast<int>(into.curves.size());
    const int p0 = static_cast<int>(into.pcurves.size());
    const int e0 = static_cast<int>(into.edges.size());
    const int f0 = static_cast<int>(into.faces.size());
    const int s0 = static_cast<int>(into.shells.size());
    const double stretch = map.stretch();
    // A mirroring map turns dP/du x dP/dv to the inside.
    const double* a = map.m;
    const double det = a[0] * (a[5] * a[10] - a[6] * a[9]) - a[1] * (a[4] * a[10] - a[6] * a[8]) +
                       a[2] * (a[4] * a[9] - a[5] * a[8]);
    for (BRepVertex v : from.vertices) {
        v.point = map(v.point);
        v.tolerance *= stretch;
        into.vertices.push_back(v);
    }
    for (BSplineCurve c : from.curves) {
        for (Vec3& p : c.points) p = map(p);
        into.curves.push_back(std::move(c));
    }
    into.pcurves.insert(into.pcurves.end(), from.pcurves.begin(), from.pcurves.end());
    for (BRepEdge e : from.edges) {
        if (e.curve >= 0) e.curve += c0;
        e.start += v0;
        e.end += v0;
        e.tolerance *= stretch;
        into.edges.push_back(e);
    }
    for (BRepFace f : from.faces) {
        f.surface += surface_offset;
        if (det < 0) f.reversed = !f.reversed;
        for (BRepLoop& loop : f.loops)
            for (BRepCoedge& ce : loop.coedges) {
                ce.edge += e0;
                ce.pcurve += p0;
            }
        into.faces.push_back(std::move(f));
    }
    for (BRepShell s : from.shells) {
        for (int& f : s.faces) f += f0;
        into.shells.push_back(std::move(s));
    }
    for (BRepSolid s : from.solids) {
        for (int& sh : s.shells) sh += s0;
        into.solids.push_back(std::move(s));
    }
}

} // namespace seamless
