// SPDX-License-Identifier: MIT
#include <seamless/model/step_iges/brep_gaps.h>

#include <seamless/model/step_iges/messages.h>

#include <algorithm>
#include <map>
#include <tuple>

namespace seamless::step_iges {
namespace {

constexpr int kSamples = 32;      // intervals per coedge
constexpr double kSlack = 1e-3;   // of the tolerance: rounding, not a gap
constexpr double kMinGap = 1e-12; // absolute: below any file's tolerance
constexpr double kMargin = 1.25;  // a raised tolerance over the gap sampled: the
                                  // parameters between samples

} // namespace

double coedge_gap(const Model& m, int face, const BRepCoedge& c) {
    const BRepEdge& e = m.brep.edges[c.edge];
    const BSplineCurve& pc = m.brep.pcurves[c.pcurve];
    const BSplineSurface& s = m.surfaces[m.brep.faces[face].surface];
    double gap = 0;
    for (int k = 0; k <= kSamples; ++k) {
        const double t = e.t0 + (e.t1 - e.t0) * k / kSamples;
        const Vec3 uv = evaluate(pc, t).point;
        const Vec3 on_surface = evaluate(s, uv.x, uv.y).point;
        const Vec3 on_edge = e.degenerate() ? m.brep.vertices[e.start].point
                                            : evaluate(m.brep.curves[e.curve], t).point;
        gap = std::max(gap, distance(on_surface, on_edge));
    }
    return gap;
}

double check_gaps(Model& m, const std::string& file) {
    BRep& b = m.brep;
    std::map<int, std::pair<double, int>> beyond; // edge -> (gap, face)
    std::vector<double> face_gap(b.faces.size(), 0);
    double worst = 0;
    for (size_t f = 0; f < b.faces.size(); ++f)
        for (const BRepLoop& loop : b.faces[f].loops)
            for (const BRepCoedge& c : loop.coedges) {
                const double gap = coedge_gap(m, static_cast<int>(f), c);
                worst = std::max(worst, gap);
                face_gap[f] = std::max(face_gap[f], gap);
                const double tol = b.edges[c.edge].tolerance;
                if (gap <= tol * (1 + kSlack) + kMinGap) continue;
                auto [it, added] = beyond.try_emplace(c.edge, gap, static_cast<int>(f));
                if (!added && it->second.first < gap) it->second = {gap, static_cast<int>(f)};
            }
    if (!beyond.empty()) {
        std::vector<std::tuple<double, int, int>> list; // gap, edge, face: largest first
        for (const auto& [edge, g] : beyond) list.emplace_back(g.first, edge, g.second);
        std::sort(list.begin(), list.end(), std::greater<>());
        std::vector<std::string> names;
        for (const auto& [gap, edge, face] : list) {
            names.push_back(b.faces[face].name + " edge " + std::to_string(edge) + " (" + fmt(gap) +
                            " > " + fmt(b.edges[edge].tolerance) + ")");
            b.edges[edge].tolerance = gap * kMargin;
        }
        m.warnings.push_back(file + ": " + count_of(list.size(), "edge") +
                             " whose pcurves stray from the 3D curve beyond the edge's "
                             "tolerance, tolerance raised to the distance: " +
                             list_names(names));
    }
    // Surfaces the conversion approximated: the error is at least what their
    // edges show.
    std::vector<std::string> approximated;
    for (size_t f = 0; f < b.faces.size(); ++f) {
        SurfaceOrigin& o = m.origins[b.faces[f].surface];
        if (o.exact) continue;
        o.approximation_error = std::max(o.approximation_error, face_gap[f]);
        approximated.push_back(o.entity + " (" + o.kind + ", " + fmt(o.approximation_error) + ")");
    }
    if (!approximated.empty())
        m.warnings.push_back(
            file + ": approximated " + count_of(approximated.size(), "surface") +
            " without an exact NURBS form, largest distances: " + list_names(approximated));
    return worst;
}

} // namespace seamless::step_iges
