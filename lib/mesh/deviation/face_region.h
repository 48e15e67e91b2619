// SPDX-License-Identifier: MIT
// The part of its surface's (u,v) domain a B-rep face is: its loops' pcurves
// sampled into polygons, a point inside when a ray from it crosses the loops
// an odd number of times (nesting parity: holes, and islands in holes, need
// no orientation). Segments are bucketed in strips of v so that a test reads
// only the segments of its strip.
#pragma once

#include <seamless/model/model.h>

#include <vector>

namespace seamless {

// Length of the polyline through n + 1 points of the curve over [t0, t1]:
// enough to choose a sample count.
double curve_length(const BSplineCurve& c, double t0, double t1, int n);

struct FaceRegionOptions {
    int samples_per_coedge = 64; // at least, and one per `spacing` of the 3D edge
    double spacing = 0;          // model units; 0: samples_per_coedge only
    int max_samples_per_coedge = 8192;
};

class FaceRegion {
  public:
    FaceRegion(const Model& model, int face, const FaceRegionOptions& options);

    // (u, v) on the face (a face without loops: its whole surface), its
    // boundary included; on a surface closed in u or v, (u, v) shifted by
    // the period that way counts too (a face's pcurves may lie one period
    // off the surface's domain).
    bool contains(double u, double v) const;
    // The loops' (u,v) bounding box (u0, v0, u1, v1).
    double u0() const { return u0_; }
    double v0() const { return v0_; }
    double u1() const { return u1_; }
    double v1() const { return v1_; }
    // (u, v) moved into the surface's domain by whole periods where closed.
    void wrap(double& u, double& v) const;

  private:
    struct Segment {
        double ua, va, ub, vb;
    };
    static double segment_distance(const Segment& s, double u, double v);
    bool contains_unshifted(double u, double v) const;
    void add_loop(const std::vector<double>& uv);
    void bucket();

    std::vector<Segment> segments_;
    std::vector<int> strip_start_, strip_segments_; // segments per strip of v (CSR)
    double u0_ = 0, v0_ = 0, u1_ = 0, v1_ = 0, strip_height_ = 1;
    double du_min_ = 0, du_max_ = 0, dv_min_ = 0, dv_max_ = 0; // surface domain
    double period_u_ = 0, period_v_ = 0;                       // 0: not closed
};

} // namespace seamless
