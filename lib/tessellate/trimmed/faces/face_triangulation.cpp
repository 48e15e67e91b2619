// SPDX-License-Identifier: MIT
#include <seamless/base/check.h>
#include <seamless/tessellate/tessellation_result.h>
#include <seamless/tessellate/trimmed/faces/constrained_triangulation.h>
#include <seamless/tessellate/trimmed/faces/face_seeds.h>
#include <seamless/tessellate/trimmed/faces/face_triangulation.h>
#include <seamless/tessellate/trimmed/faces/refinement_stop.h>
#include <seamless/tessellate/trimmed/faces/touching_loops.h>
#include <seamless/tessellate/trimmed/faces/triangle_distance.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace seamless {

namespace {

// Refinement rounds: each inserts a point in every triangle still failing.
constexpr int kRounds = 64;
// A face whose refinement does not converge (seen on a torus fillet whose
// carried pcurves stray from it) stops at this many triangles, the rest
// counted above the tolerance, instead of filling the model's budget; above
// what the corpus's largest converging faces need at a tenth of the default
// deviation (docs/results/cad.md).
constexpr size_t kMaxFaceTriangles = 250'000;
// Barycentric samples: centroid, edge midpoints (k: the edge opposite corner
// k), three points between the centroid and the corners, and on a triangle
// with a boundary side three between the centroid and the edge midpoints
// (where its largest deviation lies when the boundary side is long), and the
// inner sides' quarter points. Inside, the surface's distance to a small
// triangle is near a quadratic form that vanishes at the corners, which the
// centroid and the midpoints pin down (its maximum is at most 4/3 of the
// midpoints' largest); on a triangle long along a direction where the
// surface's curvature changes (the curvature-scaled domain's, face_domain.h)
// the distance along a side is lopsided, its largest off the midpoint.
struct Sample {
    double l[3];
    int edge;           // -1: interior
    bool boundary_only; // taken only on a triangle with a boundary side
};
constexpr Sample kSamples[] = {{{1.0 / 3, 1.0 / 3, 1.0 / 3}, -1, false},
                               {{0, 0.5, 0.5}, 0, false},
                               {{0.5, 0, 0.5}, 1, false},
                               {{0.5, 0.5, 0}, 2, false},
                               {{2.0 / 3, 1.0 / 6, 1.0 / 6}, -1, false},
                               {{1.0 / 6, 2.0 / 3, 1.0 / 6}, -1, false},
                               {{1.0 / 6, 1.0 / 6, 2.0 / 3}, -1, false},
                               {{1.0 / 6, 5.0 / 12, 5.0 / 12}, -1, true},
                               {{5.0 / 12, 1.0 / 6, 5.0 / 12}, -1, true},
                               {{5.0 / 12, 5.0 / 12, 1.0 / 6}, -1, true},
                               {{0, 0.25, 0.75}, 0, false},
                               {{0, 0.75, 0.25}, 0, false},
                               {{0.25, 0, 0.75}, 1, false},
                               {{0.75, 0, 0.25}, 1, false},
                               {{0.25, 0.75, 0}, 2, false},
                               {{0.75, 0.25, 0}, 2, false}};

// A triangle this thin (height over longest side) is a sliver.
constexpr double kSliver = 1e-3;
// A corner on a crease takes its normal this fraction of the way towards
// the triangle's centre (on the triangle's side of the crease).
constexpr double kNudge = 1e-6;
// A triangle whose sides are within this many edge tolerances is small,
// within this fraction of the deviation tiny.
constexpr double kTolerances = 8;
constexpr double kTiny = 1.0 / 8;

// Thin in the scaled domain: between loops that run along each other
// (touching_loops.h) there is no room for a point whatever the 3D corners,
// a tolerance apart, make of its normal.
bool domain_sliver(const FaceDomain& d, const std::array<int, 3>& k) {
    const Vec3 a = d.scaled[k[1]] - d.scaled[k[0]], b = d.scaled[k[2]] - d.scaled[k[0]],
               e = d.scaled[k[2]] - d.scaled[k[1]];
    return !(norm(cross(a, b)) > kSliver * std::max({dot(a, a), dot(b, b), dot(e, e)}));
}

using Verdict = TriangleVerdict;

struct Refiner {
    const FaceSurface& s;
    const FaceCriteria& c;
    FaceDomain& d;
    Vec3 inward;
    std::vector<Vec3> normal; // per point, computed once
    // Per boundary side found encroached (point indices, the smaller
    // first): the last refinement round it was, and in how many.
    std::map<std::array<int, 2>, std::array<int, 2>> encroached;
    int round = 0; // of refinement
    const AngleLimit limit = AngleLimit(c.angle);
    SpanPatches spans = SpanPatches(s.surface());

    // Sides found encroached in `rounds` rounds or more.
    std::vector<std::array<int, 2>> encroached_sides(int rounds) const {
        std::vector<std::array<int, 2>> out;
        for (const auto& [side, seen] : encroached)
            if (seen[1] >= rounds) out.push_back(side);
        return out;
    }

    Vec3 point_normal(int i) {
        while (static_cast<int>(normal.size()) <= i)
            normal.push_back(unit_normal(s, d.uv[normal.size()], inward, &spans));
        return normal[i];
    }

    // With `full` false a triangle stops being sampled once it is found
    // above the deviation: its deviation and badness are then lower bounds.
    Verdict judge(const DomainTriangle& t, bool full) {
        Verdict v;
        const auto& k = t.corners;
        std::array<Vec3, 3> uv, p;
        for (int i = 0; i < 3; ++i) uv[i] = d.uv[k[i]], p[i] = d.points[k[i]];
        for (int i = 0; i < 3; ++i) {
            const int j = (i + 1) % 3;
            if (d.keys[k[i]] >= 0 && d.keys[k[i]] == d.keys[k[j]]) {
                // Zero area: left out, which keeps the mesh closed (its two
                // other sides pair up). At a pole there is nothing to
                // approximate; across a seam the triangle is too coarse.
                v.drop = true;
                v.split = d.pole[k[i]] == Vec3{} || d.pole[k[j]] == Vec3{};
                v.badness = v.split ? INFINITY : 0;
                return v;
            }
        }
        // At a pole every (u,v) along its degenerate edge is the pole: the
        // corner stands for the one facing the other two corners.
        for (int i = 0; i < 3; ++i) {
            const Vec3 dir = d.pole[k[i]];
            if (dir == Vec3{}) continue;
            const Vec3 m = 0.5 * (uv[(i + 1) % 3] + uv[(i + 2) % 3]);
            uv[i] = uv[i] + dot(m - uv[i], dir) * dir;
        }
        const Vec3 centre = (uv[0] + uv[1] + uv[2]) / 3.0;
        // A triangle on the boundary keeps its segment's deviation, which the
        // edge's own samples held below the aim but the face's may find a
        // little above: up to D it is the edge's, not the triangle's. Not at
        // a pole, where the (u,v) samples are distorted and miss more.
        const bool pole =
            d.pole[k[0]] != Vec3{} || d.pole[k[1]] != Vec3{} || d.pole[k[2]] != Vec3{};
        const bool boundary = !pole && (t.boundary[0] || t.boundary[1] || t.boundary[2]);
        const double aim = (boundary ? 1.0 : kDeviationAim) * c.deviation;
        double excess = 0; // the largest sample's deviation over its target
        // At a pole the normal is the one facing the triangle; on a crease,
        // that of the triangle's side.
        const bool crease = s.crosses_crease(uv);
        for (int i = 0; i < 3; ++i)
            v.normals[i] = d.pole[k[i]] != Vec3{} ? unit_normal(s, uv[i], centre, &spans)
                           : crease && s.on_crease(uv[i])
                               ? unit_normal(s, uv[i] + kNudge * (centre - uv[i]), centre, &spans)
                               : point_normal(k[i]);
        const TriangleFrame frame(p[0], p[1], p[2]);
        const bool on_boundary = t.boundary[0] || t.boundary[1] || t.boundary[2];
        // Surface and flat triangle both affine in (u,v): their distance is
        // largest at a corner, its offset off the plane (which its own limit
        // allows), not sampled.
        if (s.affine())
            v.deviation = std::max({d.offset[k[0]], d.offset[k[1]], d.offset[k[2]]});
        else
            for (const Sample& smp : kSamples) {
                if (!full && excess > 1) break;
                if (smp.boundary_only && !on_boundary) continue;
                // Boundary segments were measured with their edge.
                if (smp.edge >= 0 && t.boundary[smp.edge]) continue;
                const Vec3 q = smp.l[0] * uv[0] + smp.l[1] * uv[1] + smp.l[2] * uv[2];
                // The surface's point against the flat triangle, as edges measure
                // against their chords; else the flat point against the surface.
                // At a pole the (u,v) samples miss the flat triangle's farthest
                // points (the meridians' chords), which are measured as well;
                // across a crease the flat triangle cuts the fold, which only the
                // surface's points see.
                double dev = frame.distance(s.point(q, spans));
                const Vec3 flat = smp.l[0] * p[0] + smp.l[1] * p[1] + smp.l[2] * p[2];
                // Above the aim only what the corners' offsets off the surface
                // force, whatever the tolerances of the face's edges.
                const double limit_here =
                    aim + offset_allowance(d.offset_at(k, smp.l), c.deviation);
                if (pole || crease)
                    dev = std::max(dev, distance_to_surface(s, spans, flat, q, 0));
                else if (dev > limit_here)
                    dev = std::min(dev, distance_to_surface(s, spans, flat, q, limit_here));
                v.deviation = std::max(v.deviation, dev);
                excess = std::max(excess, dev / limit_here);
            }
        // The corner normals within the angle of each other, and the flat
        // triangle's within it of theirs: no fold or needle on the surface.
        // Across a crease the normal jumps however small the triangle, and a
        // sliver between three boundary points (a boundary polyline's kink of
        // a rounding) or an ear of two boundary segments (the sag between a
        // curved edge's polyline and its chord, standing off the surface) has
        // no room for a point and no normal of its own: the deviation alone
        // judges those.
        const Vec3 a = p[1] - p[0], b = p[2] - p[0], e = p[2] - p[1];
        const Vec3 n = cross(a, b);
        const double longest = std::max({dot(a, a), dot(b, b), dot(e, e)});
        const bool ear =
            (t.boundary[0] + t.boundary[1] + t.boundary[2] >= 2) ||
            (k[0] < d.boundary_points && k[1] < d.boundary_points && k[2] < d.boundary_points &&
             (!(norm(n) > kSliver * longest) || domain_sliver(d, k)));
        // Boundary points lie on their edge's curve, up to the edge's
        // tolerance off the surface: a triangle within a few tolerances has
        // a flat normal the tolerance tilts, and only its corners' count. A
        // triangle within a fraction of D is judged by its deviation alone:
        // at an apex or a pole the normals turn however small it is.
        const bool tiny = longest <= kTiny * kTiny * c.deviation * c.deviation;
        const bool small = tiny || longest <= kTolerances * kTolerances * d.tolerance * d.tolerance;
        double turn = 0;
        // Turns within the angle do not matter (the badness of a triangle
        // that meets the limits is not used).
        if (!ear && !crease && !tiny)
            for (int i = 0; i < 3; ++i) {
                const Vec3 x = v.normals[i], y = v.normals[(i + 1) % 3];
                if (limit.exceeded(x, y)) turn = std::max(turn, angle_between(x, y));
                if (!small && limit.exceeded(x, n)) turn = std::max(turn, angle_between(x, n));
            }
        const bool flat = !ear && !(norm(n) > 1e-12 * longest);
        v.badness = flat ? INFINITY : std::max(excess, turn / c.angle);
        v.split = v.badness > 1;
        return v;
    }

    // Records t's boundary sides that the point `at`, refused, encroaches;
    // false when there are none. Not a side along a pole's degenerate edge,
    // which halving would not change (all its points are the pole), nor,
    // on a triangle of three mesh vertices, a side leaving a pole with `at`
    // on t's side of it and outside its diametral circle (Ruppert's test):
    // `at` then lies beside the degenerate edge, and halving the side would
    // only move its other end towards the pole. (A triangle across a seam,
    // two of its corners one vertex, has its seam sides halved.)
    bool record_encroached(const DomainTriangle& t, Vec3 at) {
        const auto& c = t.corners;
        const bool seam =
            (d.keys[c[0]] >= 0 && (d.keys[c[0]] == d.keys[c[1]] || d.keys[c[0]] == d.keys[c[2]])) ||
            (d.keys[c[1]] >= 0 && d.keys[c[1]] == d.keys[c[2]]);
        bool any = false;
        for (int k = 0; k < 3; ++k) {
            const int a = c[(k + 1) % 3], b = c[(k + 2) % 3];
            if (!t.boundary[k] || (d.pole[a] != Vec3{} && d.pole[b] != Vec3{})) continue;
            if (!seam && (d.pole[a] != Vec3{} || d.pole[b] != Vec3{}) &&
                !d.encroaches(at, a, b, c[k]))
                continue;
            auto& seen = encroached[{std::min(a, b), std::max(a, b)}];
            if (seen[1] == 0 || seen[0] != round) seen = {round, seen[1] + 1};
            any = true;
        }
        return any;
    }

    // The point to insert for t: its circumcentre where that lies in the
    // domain clear of constraints (Delaunay: no earlier point lies inside its
    // circumcircle, so one nearer than half the radius was inserted for a
    // neighbour in this round, and t is left to the next). Where it does not
    // and t has a boundary side, that side is encroached (Ruppert): a point
    // near it would make a sliver whose flat side is the segment's chord,
    // which can stray from the surface (a curved edge on a narrow face), so
    // the side is recorded for halving instead. Else t's centroid.
    bool insert_for(ConstrainedTriangulation& cdt, const DomainTriangle& t) {
        const Vec3 a = d.scaled[t.corners[0]], b = d.scaled[t.corners[1]],
                   c3 = d.scaled[t.corners[2]];
        const Vec3 ab = b - a, ac = c3 - a;
        const double den = 2 * (ab.x * ac.y - ab.y * ac.x);
        const double shortest =
            std::sqrt(std::min({dot(ab, ab), dot(ac, ac), dot(c3 - b, c3 - b)}));
        if (!(shortest > 0) || den == 0) return false;
        const double ab2 = dot(ab, ab), ac2 = dot(ac, ac);
        const Vec3 offset{(ac.y * ab2 - ab.y * ac2) / den, (ab.x * ac2 - ac.x * ab2) / den, 0};
        Vec3 at = a + offset;
        int index = cdt.insert(at, 0.75 * norm(offset), t.corners[0]);
        if (index == ConstrainedTriangulation::kCrowded) return false;
        if (index == ConstrainedTriangulation::kOutside && record_encroached(t, at)) return false;
        if (index < 0) index = cdt.insert(at = (a + b + c3) / 3.0, 1e-3 * shortest, t.corners[0]);
        if (index < 0) return false;
        SEAMLESS_CHECK(index == d.size(), "the triangulation numbers inserted points in order");
        d.add_interior(s, at);
        return true;
    }
};

// A face whose every edge is degenerate is a point in space: nothing to
// mesh, and no neighbour shares a mesh edge with it.
bool collapsed(const BRep& brep, const BRepFace& f) {
    for (const BRepLoop& loop : f.loops)
        for (const BRepCoedge& c : loop.coedges)
            if (!brep.edges[c.edge].degenerate()) return false;
    return true;
}

} // namespace

FaceMesh triangulate_face(const Model& model, const std::vector<EdgePolyline>& lines, int face,
                          const FaceCriteria& criteria, const FaceMesh* seeds) {
    const BRepFace& f = model.brep.faces[face];
    FaceMesh out;
    if (collapsed(model.brep, f)) return out;
    const FaceSurface s(model.surfaces[f.surface]);
    out.domain = face_domain(model, lines, face);
    FaceDomain& d = out.domain;
    ConstrainedTriangulation cdt;
    if (!cdt.build(d.scaled, d.keys, d.segments) &&
        !(separate_touching_loops(model.brep, s, d) && cdt.build(d.scaled, d.keys, d.segments))) {
        out.failed = true;
        return out;
    }
    if (seeds) insert_seeds(s, seeds->domain, d, cdt);
    Refiner r{s, criteria, d, face_uv_centre(model.brep, f), {}, {}, 0};
    // The earlier run's verdicts hold where the face's tolerance is as it
    // was, and, for a triangle of three boundary points (its ear test looks
    // at the scaled domain), the scale too (triangle_verdict.h).
    const AcceptedTriangles* known =
        seeds && seeds->domain.tolerance == d.tolerance ? &seeds->accepted : nullptr;
    const bool same_scale = seeds && seeds->domain.su == d.su && seeds->domain.sv == d.sv;
    auto reusable = [&](const DomainTriangle& t) {
        return known && (same_scale || t.corners[0] >= d.boundary_points ||
                         t.corners[1] >= d.boundary_points || t.corners[2] >= d.boundary_points);
    };
    auto corners_uv = [&](const DomainTriangle& t) {
        return std::array<Vec3, 3>{d.uv[t.corners[0]], d.uv[t.corners[1]], d.uv[t.corners[2]]};
    };
    std::vector<DomainTriangle> tris;
    // Verdicts, by the triangles' tags: a triangle the insertions left alone
    // keeps its verdict.
    std::vector<Verdict> judged;
    long long reused = 0; // verdicts the earlier run's
    std::vector<int> failing;
    bool stopped = false; // by FaceCriteria::stop_when_encroached
    RefinementStop stop(d.boundary_points);
    for (int round = 0;; ++round) {
        cdt.triangles(tris);
        if (static_cast<std::int64_t>(tris.size()) > criteria.max_triangles)
            throw TriangleBudgetError(model.source, "brep.faces[" + std::to_string(face) + "]",
                                      criteria.max_triangles);
        failing.clear();
        for (size_t i = 0; i < tris.size(); ++i) {
            if (tris[i].tag < 0) {
                tris[i].tag = static_cast<int>(judged.size());
                Verdict v;
                if (reusable(tris[i]) && known->find(corners_uv(tris[i]), tris[i].boundary, v))
                    ++reused;
                else
                    v = r.judge(tris[i], false);
                judged.push_back(v);
                cdt.set_tag(static_cast<int>(i), tris[i].tag);
            }
            if (judged[tris[i].tag].split) failing.push_back(static_cast<int>(i));
        }
        if (round == kRounds || failing.empty() || tris.size() > kMaxFaceTriangles) break;
        const bool due = stop.due(round, failing.size(), tris.size());
        if (criteria.stop_when_encroached && due &&
            !r.encroached_sides(kPersistentEncroachment).empty()) {
            stopped = true;
            break;
        }
        r.round = round;
        // The worst first: their points make room that their neighbours' need not.
        std::stable_sort(failing.begin(), failing.end(), [&](int a, int b) {
            return judged[tris[a].tag].badness > judged[tris[b].tag].badness;
        });
        bool inserted = false;
        for (int i : failing)
            if (r.insert_for(cdt, tris[i])) inserted = true;
        if (!inserted) break;
    }
    out.crowded = stopped && stop.crowded(tris.size());
    if (stopped)
        out.encroached = d.segments_joining(r.encroached_sides(kPersistentEncroachment));
    else if (!failing.empty())
        out.encroached = d.segments_joining(r.encroached_sides(1));
    out.judged = static_cast<long long>(judged.size()) - reused;
    for (const DomainTriangle& t : tris) {
        Verdict& v = judged[t.tag];
        if (v.split && !v.drop) v = r.judge(t, true);
        if (!v.split) out.accepted.add(corners_uv(t), t.boundary, v);
        if (v.drop) continue;
        if (v.split) ++out.above_tolerance;
        out.deviation = std::max(out.deviation, v.deviation);
        std::array<int, 3> c = t.corners;
        std::array<Vec3, 3> n = v.normals;
        if (f.reversed) {
            std::swap(c[1], c[2]);
            std::swap(n[1], n[2]);
            for (Vec3& x : n) x = -x;
        }
        out.triangles.push_back(c);
        out.normals.push_back(n);
    }
    out.accepted.seal();
    return out;
}

} // namespace seamless
