// SPDX-License-Identifier: MIT
#include <seamless/mesh/deviation/brep_samples.h>

#include <algorithm>
#include <cmath>

namespace seamless {
namespace {

int count_for(double length, double spacing, int lo, int hi) {
    if (!(spacing > 0) || !(length > 0)) return lo;
    return static_cast<int>(std::clamp(std::ceil(length / spacing), double(lo), double(hi)));
}

// Longest of three polylines across the face's (u,v) box in one direction:
// its 3D extent that way.
double extent_along(const BSplineSurface& s, const FaceRegion& r, bool along_u) {
    constexpr int kSteps = 16;
    double longest = 0;
    for (const double f : {0.0, 0.5, 1.0}) {
        double length = 0;
        Vec3 prev{};
        for (int i = 0; i <= kSteps; ++i) {
            const double g = double(i) / kSteps;
            double u = r.u0() + (along_u ? g : f) * (r.u1() - r.u0());
            double v = r.v0() + (along_u ? f : g) * (r.v1() - r.v0());
            r.wrap(u, v);
            const Vec3 p = evaluate(s, u, v).point;
            if (i > 0) length += distance(prev, p);
            prev = p;
        }
        longest = std::max(longest, length);
    }
    return longest;
}

} // namespace

std::vector<FaceSample> face_samples(const Model& model, int face, const FaceRegion& region,
                                     const BRepSamplingOptions& options) {
    const BSplineSurface& s = model.surfaces[model.brep.faces[face].surface];
    const int nu = count_for(extent_along(s, region, true), options.spacing, options.min_grid,
                             options.max_grid);
    const int nv = count_for(extent_along(s, region, false), options.spacing, options.min_grid,
                             options.max_grid);
    std::vector<FaceSample> out;
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            double u = region.u0() + (i + 0.5) / nu * (region.u1() - region.u0());
            double v = region.v0() + (j + 0.5) / nv * (region.v1() - region.v0());
            if (!region.contains(u, v)) continue;
            region.wrap(u, v);
            out.push_back({evaluate(s, u, v).point, face, u, v});
        }
    return out;
}

std::vector<EdgeSample> edge_samples(const Model& model, int edge,
                                     const BRepSamplingOptions& options) {
    const BRepEdge& e = model.brep.edges[edge];
    if (e.degenerate()) return {};
    const BSplineCurve& c = model.brep.curves[e.curve];
    const double length = curve_length(c, e.t0, e.t1, 32);
    const int n =
        count_for(length, options.spacing, options.min_edge_samples, options.max_edge_samples);
    std::vector<EdgeSample> out;
    for (int i = 0; i <= n; ++i) {
        const double t = e.t0 + (e.t1 - e.t0) * i / n;
        out.push_back({evaluate(c, t).point, edge, t});
    }
    return out;
}

double brep_diagonal(const Model& model) {
    Box3 box;
    for (const BRepVertex& v : model.brep.vertices) box.extend(v.point);
    for (const BSplineCurve& c : model.brep.curves)
        for (const Vec3& p : c.points) box.extend(p);
    if (box.empty()) box = control_box(model);
    return norm(box.extent());
}

} // namespace seamless
