// SPDX-License-Identifier: MIT
// Certified clusters and exact intensities of their rays, for tests that
// check INTRACY's enclosures of intensities against sampled values.
#pragma once

#include <seamless/render/pixels/pixel_solve.h>
#include <seamless/render/scene/projection.h>
#include <seamless/render/shading/shading.h>
#include <seamless/render/subscreen/primary_cluster.h>

#include <array>

namespace seamless::test {

// The exact intensity of the ray through (a, b) on patch pp in box (Newton in
// doubles; a cluster's certificate says the hit is unique there), lit by
// `lighting` (camera coordinates).
inline bool exact_intensity(const Scene& lighting, const ProjectedPatch& pp, const ParamBox& box,
                            double a, double b, std::array<double, 3>& I) {
    double s, t;
    if (!newton_corner(pp.patch, a, b, box, s, t)) return false;
    Vec3 P, N;
    surface_frame(pp.patch, s, t, P, N);
    I = shade<double>(lighting, lighting.materials[pp.material], to_v3(P), to_v3(N), Vec3{});
    return true;
}

// A certified cluster of the rays through [a] x [b] on patch pp (Theorem 6
// iii, certify_cluster): its system in sys, its contracted box in box. The
// renderer reaches such boxes by narrowing from its parents'; here the box
// starts around the hit of the middle ray (Newton in a cell of the patch),
// 0.005, 0.02 or 0.08 wide each way, or as the whole patch narrowed.
inline bool certified_cluster(const ProjectedPatch& pp, Interval a, Interval b, ClusterSystem& sys,
                              ParamBox& box) {
    cluster_system(pp.forms, a, b, sys);
    double s = 0, t = 0;
    bool centre = false; // Newton from the middles of a 4 x 4 grid of cells, kept in the cell
    for (int k = 0; k < 16 && !centre; ++k) {
        const ParamBox cell{Interval((k & 3) / 4.0, ((k & 3) + 1) / 4.0),
                            Interval((k >> 2) / 4.0, ((k >> 2) + 1) / 4.0)};
        centre = newton_corner(pp.patch, a.mid(), b.mid(), cell, s, t);
    }
    for (const double d : {0.005, 0.02, 0.08, 1.0}) {
        box = d < 1 && centre ? ParamBox{intersect(Interval(s - d, s + d), Interval(0.0, 1.0)),
                                         intersect(Interval(t - d, t + d), Interval(0.0, 1.0))}
                              : ParamBox{};
        if (narrow(sys, box) && certify_cluster(sys, box)) return true;
        if (!centre) break;
    }
    return false;
}

} // namespace seamless::test
