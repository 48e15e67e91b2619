// SPDX-License-Identifier: MIT
// Topology first (issue 28, section 2): every B-rep edge is discretised once
// into one polyline that every face using it shares by index. A segment is
// split until its chord is within the deviation of the 3D curve, the curve's
// tangent turns by at most the angle along it, and on every face using the
// edge the straight (u,v) segment between its pcurve points maps within the
// deviation of the chord, with the surface normal turning by at most the
// angle (OpenCASCADE's BRepMesh_CurveTessellator checks the (u,v) chord too).
// Nothing inserts a point on a segment afterwards but halve_segments, which
// both sides see.
#pragma once

#include <seamless/model/brep.h>
#include <seamless/tessellate/trimmed/face_surface.h>

#include <vector>

namespace seamless {

// One face's view of an edge.
struct EdgeOnFace {
    FaceSurface surface;
    const BSplineCurve* pcurve = nullptr;
    double tolerance = 0; // the edge's: how far S(pcurve) may be from the curve
    // A (u,v) point inside the face: the normal at a pole or apex is taken
    // from a step towards it.
    Vec3 inward;
};

// Edges and faces aim this fraction of D below it: samples miss the largest
// deviation, which lies between them, by a few per cent.
constexpr double kDeviationAim = 0.9;

// What a chord or a triangle whose ends or corners lie `offset` off the
// surface (interpolated between them; an edge's point on its curve against
// the surface at its pcurve's point) may be measured above its aim: up to
// 0.8 D the offset leaves the surface's sag a tenth of D below the aim, and
// beyond, the offset's excess is what no refinement removes.
inline double offset_allowance(double offset, double deviation) {
    constexpr double kFree = kDeviationAim - 0.1;
    return offset > kFree * deviation ? offset - kFree * deviation : 0;
}

struct EdgeCriteria {
    double deviation = 0; // D, model units
    double angle = 0.5;   // radians
    int max_points = 1 << 16;
};

struct EdgePolyline {
    std::vector<double> t;    // increasing from the edge's t0 to t1
    std::vector<Vec3> points; // 3D points; the ends (and a degenerate edge's all) are its vertices
    double deviation = 0;     // largest sampled chord deviation, model units
    bool limited = false;     // a segment stopped by the depth or point limit
};

EdgePolyline discretise_edge(const BRep& brep, int edge, const std::vector<EdgeOnFace>& uses,
                             const EdgeCriteria& criteria);

// Inserts the midpoint of each listed segment (k: between points k and
// k + 1; sorted), or of every segment when the list is empty: a face whose
// loops did not triangulate gets finer loops, and so does every other face
// of the edge.
void halve_segments(const BRep& brep, int edge, EdgePolyline& line,
                    const std::vector<int>& segments = {});

// The unit normal dP/du x dP/dv at uv; where it vanishes (a pole, an apex),
// the normal a small step towards `inward`; zero if that vanishes too.
// With `spans` (the surface's), evaluated on its Bezier patches.
Vec3 unit_normal(const FaceSurface& s, Vec3 uv, Vec3 inward, SpanPatches* spans = nullptr);

// Angle in radians between two vectors (0 when one is zero).
double angle_between(Vec3 a, Vec3 b);

// The angle limit, tested as angle_between(a, b) > angle is, to the same
// verdict: the cosine settles all but the near-equal cases without atan2
// (every judged triangle tests six pairs of normals).
class AngleLimit {
  public:
    explicit AngleLimit(double angle);
    bool exceeded(Vec3 a, Vec3 b) const;

  private:
    double angle_, cos2_;
};

} // namespace seamless
