// SPDX-License-Identifier: MIT
#include <seamless/mesh/deviation/brep_samples.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace seamless {
namespace {

int count_for(double length, double spacing, int lo, int hi) {
    if (!(spacing > 0) || !(length > 0)) return lo;
    return static_cast<int>(std::clamp(std::ceil(length / spacing), double(lo), double(hi)));
}

// Cells of a face's grid each way for 3D extents lu and lv: `spacing` apart,
// at least min_grid each way and at most max_grid^2 in all, shrunk alike both
// ways past that. A budget in all rather than a cap each way: a thread's
// helical band, 170 mm long over 9 turns and 0.5 mm wide, had 400 cells 0.42
// mm apart along it, 12 times its neighbours' spacing, so that a point's
// nearest samples all lay on the neighbours and the band was never projected
// on (docs/results/cad.md, b123d).
std::pair<int, int> grid_counts(double lu, double lv, const BRepSamplingOptions& o) {
    constexpr double kMost = 1e9;
    const double lo = o.min_grid, budget = double(o.max_grid) * o.max_grid;
    double nu = count_for(lu, o.spacing, o.min_grid, int(kMost));
    double nv = count_for(lv, o.spacing, o.min_grid, int(kMost));
    if (nu * nv > budget) {
        const double shrink = std::sqrt(budget / (nu * nv));
        nu = std::max(lo, std::floor(nu * shrink));
        nv = std::max(lo, std::floor(nv * shrink));
        nu = std::max(lo, std::min(nu, std::floor(budget / nv)));
        nv = std::max(lo, std::min(nv, std::floor(budget / nu)));
    }
    return {static_cast<int>(nu), static_cast<int>(nv)};
}

// Distinct knot spans of the surface in one direction.
int spans(const BSplineSurface& s, bool along_u) {
    const std::vector<double>& k = along_u ? s.knots_u : s.knots_v;
    const double lo = along_u ? s.u_min() : s.v_min(), hi = along_u ? s.u_max() : s.v_max();
    int n = 0;
    for (size_t i = 1; i < k.size(); ++i) n += k[i] > k[i - 1] && k[i - 1] >= lo && k[i] <= hi;
    return std::max(n, 1);
}

// Longest of three polylines across the face's (u,v) box in one direction:
// its 3D extent that way. Four steps per knot span at least, so that a
// surface turning many times (a helix's band) is not measured by chords
// across its turns.
double extent_along(const BSplineSurface& s, const FaceRegion& r, bool along_u) {
    const int kSteps = std::clamp(4 * spans(s, along_u), 16, 1024);
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
    const auto [nu, nv] =
        grid_counts(extent_along(s, region, true), extent_along(s, region, false), options);
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
