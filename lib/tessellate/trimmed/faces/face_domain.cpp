// SPDX-License-Identifier: MIT
#include <seamless/base/check.h>
#include <seamless/tessellate/trimmed/faces/face_domain.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace seamless {

std::int64_t boundary_key(const BRep& brep, int edge, int k, const EdgePolyline& line) {
    const BRepEdge& e = brep.edges[edge];
    if (k == 0 || e.degenerate()) return e.start;
    if (k == static_cast<int>(line.t.size()) - 1) return e.end;
    return edge_point_key(edge, k);
}

Vec3 face_uv_centre(const BRep& brep, const BRepFace& face) {
    Box3 box;
    for (const BRepLoop& loop : face.loops)
        for (const BRepCoedge& c : loop.coedges)
            for (const Vec3& p : brep.pcurves[c.pcurve].points) box.extend(p);
    return box.empty() ? Vec3{} : 0.5 * (box.lo + box.hi);
}

namespace {

// Mean |dP/du| and |dP/dv| over a grid on the (u,v) box, each times the
// square root of the surface's mean normal curvature that way: a triangle
// meets a deviation over a length proportional to 1 / sqrt(curvature), so
// that a unit step either way costs about the same deviation and Delaunay's
// round triangles are long along a cylinder's rulings (at most kAspect to
// one), as a chordal tessellation's are. Curvature from the normal's turn
// between neighbouring grid points per their distance.
void domain_scale(const FaceSurface& s, const Box3& box, double& su, double& sv) {
    constexpr int kGrid = 5;
    constexpr double kAspect = 4;
    SurfacePoint p[kGrid][kGrid];
    Vec3 n[kGrid][kGrid];
    double lu = 0, lv = 0;
    for (int i = 0; i < kGrid; ++i)
        for (int j = 0; j < kGrid; ++j) {
            p[i][j] = s.at({box.lo.x + (box.hi.x - box.lo.x) * (i + 0.5) / kGrid,
                            box.lo.y + (box.hi.y - box.lo.y) * (j + 0.5) / kGrid, 0});
            n[i][j] = normalize(p[i][j].normal());
            lu += norm(p[i][j].du);
            lv += norm(p[i][j].dv);
        }
    const auto turn = [&](int i, int j, int k, int l) {
        const double d = distance(p[i][j].point, p[k][l].point);
        if (!(d > 0) || n[i][j] == Vec3{} || n[k][l] == Vec3{}) return 0.0;
        return 2 * std::asin(std::min(1.0, 0.5 * distance(n[i][j], n[k][l]))) / d;
    };
    double ku = 0, kv = 0;
    for (int i = 0; i < kGrid; ++i)
        for (int j = 0; j + 1 < kGrid; ++j) {
            ku += turn(j, i, j + 1, i);
            kv += turn(i, j, i, j + 1);
        }
    su = lu > 0 ? lu : lv > 0 ? lv : kGrid * kGrid;
    sv = lv > 0 ? lv : su;
    // Only the ratio matters to Delaunay; the mean keeps the model's scale.
    su /= kGrid * kGrid;
    sv /= kGrid * kGrid;
    const double most = std::max(ku, kv), floor = most / (kAspect * kAspect);
    if (!(most > 0) || !std::isfinite(most)) return;
    const double r = std::sqrt(std::sqrt(std::max(ku, floor) / std::max(kv, floor)));
    su *= r;
    sv /= r;
}

// The pcurves of two edges meeting at a vertex end at (u,v) points a
// rounding or the vertex's tolerance apart; left apart, the constrained
// triangulation sees two points and the segments leaving them cross where
// the loops meet at a small angle. Images of one vertex closer than its
// tolerance (on the scaled domain, whose unit is one model unit within a
// factor of two each way) or than rounding are made one; a seam's or a
// pole's images are far apart.
// Not where they are farther apart than a fraction of a boundary segment
// leaving either: on a face smaller than its tolerance a closed edge's two
// ends would fold the loop back on itself.
void merge_vertex_images(const BRep& brep, const Box3& box, FaceDomain& d) {
    constexpr double kSegmentFraction = 0.25;
    const double rounding =
        1e-12 * norm(Vec3{(box.hi.x - box.lo.x) * d.su, (box.hi.y - box.lo.y) * d.sv, 0});
    std::vector<double> shortest(d.size(), std::numeric_limits<double>::infinity());
    for (const auto& [a, b] : d.segments) {
        const double l = distance(d.scaled[a], d.scaled[b]);
        shortest[a] = std::min(shortest[a], l);
        shortest[b] = std::min(shortest[b], l);
    }
    std::vector<std::pair<std::int64_t, int>> first; // key, first image
    for (int i = 0; i < d.size(); ++i) {
        if (!is_vertex_key(d.keys[i])) continue;
        const double near =
            std::max(rounding, brep.vertices[static_cast<size_t>(d.keys[i])].tolerance);
        bool merged = false;
        for (const auto& [key, j] : first)
            if (key == d.keys[i] &&
                distance(d.scaled[i], d.scaled[j]) <=
                    std::max(rounding, std::min(near, kSegmentFraction *
                                                          std::min(shortest[i], shortest[j])))) {
                d.uv[i] = d.uv[j];
                d.scaled[i] = d.scaled[j];
                merged = true;
                break;
            }
        if (!merged) first.push_back({d.keys[i], i});
    }
}

} // namespace

int FaceDomain::add_interior(const FaceSurface& s, Vec3 at) {
    return add_interior(s, at, {at.x / su, at.y / sv, 0});
}

int FaceDomain::add_interior(const FaceSurface& s, Vec3 at, Vec3 p) {
    uv.push_back(p);
    scaled.push_back(at);
    points.push_back(s.point(p)); // at(p).point to the bit, without derivatives
    keys.push_back(-1);
    pole.push_back({});
    offset.push_back(0);
    return size() - 1;
}

bool FaceDomain::encroaches(Vec3 at, int a, int b, int c) const {
    const Vec3 pa = scaled[a], pb = scaled[b], side = pb - pa;
    const Vec3 ta = at - pa, ca = scaled[c] - pa;
    const double across = (side.x * ta.y - side.y * ta.x) * (side.x * ca.y - side.y * ca.x);
    return !(across > 0) || distance(at, 0.5 * (pa + pb)) < 0.5 * norm(side);
}

std::vector<int> FaceDomain::segments_joining(std::vector<std::array<int, 2>> sides) const {
    for (auto& s : sides) s = {std::min(s[0], s[1]), std::max(s[0], s[1])};
    std::sort(sides.begin(), sides.end());
    sides.erase(std::unique(sides.begin(), sides.end()), sides.end());
    std::vector<int> out;
    for (size_t i = 0; i < segments.size(); ++i) {
        const std::array<int, 2> s{std::min(segments[i][0], segments[i][1]),
                                   std::max(segments[i][0], segments[i][1])};
        if (std::binary_search(sides.begin(), sides.end(), s)) out.push_back(static_cast<int>(i));
    }
    return out;
}

FaceDomain face_domain(const Model& model, const std::vector<EdgePolyline>& lines, int face) {
    const BRep& brep = model.brep;
    const BRepFace& f = brep.faces[face];
    FaceDomain d;
    for (const BRepLoop& loop : f.loops) {
        const int first = d.size();
        for (const BRepCoedge& c : loop.coedges) {
            const EdgePolyline& line = lines[c.edge];
            const BRepEdge& e = brep.edges[c.edge];
            const BSplineCurve& pc = brep.pcurves[c.pcurve];
            d.tolerance = std::max(d.tolerance, e.tolerance);
            const int n = static_cast<int>(line.t.size());
            Vec3 pole;
            if (e.degenerate())
                pole = normalize(evaluate_point(pc, e.t1) - evaluate_point(pc, e.t0));
            // The last point is the next coedge's first (the same vertex).
            for (int j = 0; j + 1 < n; ++j) {
                const int k = c.reversed ? n - 1 - j : j;
                d.uv.push_back(evaluate_point(pc, line.t[k]));
                d.points.push_back(line.points[k]);
                d.keys.push_back(boundary_key(brep, c.edge, k, line));
                d.pole.push_back(pole);
                d.origins.push_back({c.edge, c.reversed ? k - 1 : k, c.pcurve});
            }
        }
        const int last = d.size();
        for (int i = first; i < last; ++i) d.segments.push_back({i, i + 1 < last ? i + 1 : first});
    }
    SEAMLESS_CHECK(d.origins.size() == d.segments.size(), "one origin per loop segment");
    d.boundary_points = d.size();
    // A pole's vertex where another edge meets it is the pole as well.
    std::vector<std::pair<std::int64_t, Vec3>> poles;
    for (int i = 0; i < d.size(); ++i)
        if (d.pole[i] != Vec3{} && (poles.empty() || poles.back().first != d.keys[i]))
            poles.push_back({d.keys[i], d.pole[i]});
    for (int i = 0; i < d.size() && !poles.empty(); ++i)
        for (const auto& [key, dir] : poles)
            if (d.keys[i] == key && d.pole[i] == Vec3{}) d.pole[i] = dir;
    Box3 box;
    for (const Vec3& p : d.uv) box.extend(p);
    const FaceSurface s(model.surfaces[f.surface]);
    domain_scale(s, box, d.su, d.sv);
    for (const Vec3& p : d.uv) d.scaled.push_back({p.x * d.su, p.y * d.sv, 0});
    merge_vertex_images(brep, box, d);
    // After the merge, which moves a vertex's images onto one (u,v) point.
    for (int i = 0; i < d.size(); ++i) d.offset.push_back(distance(d.points[i], s.point(d.uv[i])));
    return d;
}

} // namespace seamless
