// SPDX-License-Identifier: MIT
#include <seamless/tessellate/trimmed/faces/constrained_triangulation.h>
#include <seamless/tessellate/trimmed/faces/touching_loops.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace seamless {

namespace {

// Rounds of moving: each moves the point nearest each crossing, so a run of
// points on the wrong side shrinks from both of its ends.
constexpr int kRounds = 64;
// How far inside the face a moved point lies, as a fraction of the distance
// allowed: enough for the exact predicates to see the face's side, too
// little to matter to the surface.
constexpr double kInside = 1e-2;
// A point moves at most this fraction of its shorter segment: a larger move
// would change the loop's shape, not only its side.
constexpr double kSegmentFraction = 0.25;

// By segment (= by its first point): +1 where the face lies to the left of
// it, -1 to the right. The outer loop (loops[0]) has the face inside, the
// holes outside; a loop's direction comes from its signed area, since files
// keep the direction they have.
std::vector<int> face_sides(const FaceDomain& d) {
    std::vector<int> side(d.segments.size(), 1);
    for (int first = 0, loop = 0; first < static_cast<int>(d.segments.size()); ++loop) {
        int last = first;
        while (d.segments[last][1] != first) ++last;
        double area = 0;
        for (int i = first; i <= last; ++i) {
            const Vec3 a = d.scaled[d.segments[i][0]], b = d.scaled[d.segments[i][1]];
            area += a.x * b.y - a.y * b.x;
        }
        std::fill(side.begin() + first, side.begin() + last + 1,
                  (area > 0) == (loop == 0) ? 1 : -1);
        first = last + 1;
    }
    return side;
}

struct Move {
    int point = -1;
    Vec3 to;
    double distance = std::numeric_limits<double>::infinity();
};

struct Separation {
    const BRep& brep;
    const FaceSurface& surface;
    FaceDomain& d;
    std::vector<int> side;
    std::vector<double> mismatch; // by edge: -1 until measured

    double tolerance(int segment) const { return brep.edges[d.origins[segment].edge].tolerance; }
    // An edge's inner point: B-rep vertices and poles are where loops meet
    // by design, and their images are merged across coedges.
    bool movable(int p) const {
        return p < static_cast<int>(d.segments.size()) && !is_vertex_key(d.keys[p]) &&
               d.pole[p] == Vec3{};
    }
    // Largest distance between the surface at an edge's (u,v) images on this
    // face and its 3D points: of two edges that cross, the one whose pcurve
    // is the rougher fit moves (an iso-line along a domain side stays).
    double fit(int edge) {
        double& m = mismatch[edge];
        if (m >= 0) return m;
        m = 0;
        for (size_t i = 0; i < d.segments.size(); ++i)
            if (d.origins[i].edge == edge && movable(static_cast<int>(i)))
                m = std::max(m, d.offset[i]);
        return m;
    }
    int previous(int p) const {
        if (p > 0 && d.segments[p - 1][1] == p) return p - 1;
        const auto at = std::find_if(d.segments.begin(), d.segments.end(),
                                     [&](const std::array<int, 2>& s) { return s[1] == p; });
        return static_cast<int>(at - d.segments.begin());
    }
    double shorter_segment(int p) const {
        return std::min(distance(d.scaled[p], d.scaled[d.segments[p][1]]),
                        distance(d.scaled[p], d.scaled[d.segments[previous(p)][0]]));
    }
    // Point p of the other segment, on segment s's wrong side (or on it)
    // within tolerance of its line: where it would lie just inside the face.
    void consider(int p, int s, Move& best) const {
        const std::array<int, 2>& ab = d.segments[s];
        if (!movable(p) || p == ab[0] || p == ab[1]) return;
        const Vec3 a = d.scaled[ab[0]], b = d.scaled[ab[1]], q = d.scaled[p];
        const Vec3 along = b - a;
        const double length = norm(along);
        if (!(length > 0)) return;
        const Vec3 inward = (side[s] / length) * Vec3{-along.y, along.x, 0};
        if (dot(q - a, inward) > 0) return;
        // Onto the segment's line: the point beyond the crossing may lie
        // beside the next segment along (collinear with this one).
        const Vec3 foot = a + (dot(q - a, along) / (length * length)) * along;
        const double allowed =
            std::min(std::max(tolerance(p), tolerance(s)), kSegmentFraction * shorter_segment(p));
        const double off = distance(q, foot);
        if (off <= allowed && off < best.distance)
            best = {p, foot + kInside * allowed * inward, off};
    }
    // Of a crossing pair, the rougher edge's end points move (both edges'
    // when the pair is one edge's), the nearest to the other segment.
    Move choose(const ConstrainedTriangulation::Conflict& c) {
        const int ea = d.origins[c.a].edge, eb = d.origins[c.b].edge;
        const bool a_moves = ea == eb || fit(ea) >= fit(eb);
        const bool b_moves = ea == eb || fit(eb) >= fit(ea);
        Move best;
        if (a_moves)
            for (int p : d.segments[c.a]) consider(p, c.b, best);
        if (b_moves)
            for (int p : d.segments[c.b]) consider(p, c.a, best);
        return best;
    }
    void move(const Move& m) {
        d.scaled[m.point] = m.to;
        d.uv[m.point] = {m.to.x / d.su, m.to.y / d.sv, 0};
        d.offset[m.point] = distance(d.points[m.point], surface.point(d.uv[m.point]));
    }
};

} // namespace

bool separate_touching_loops(const BRep& brep, const FaceSurface& surface, FaceDomain& d) {
    Separation sep{brep, surface, d, face_sides(d), std::vector<double>(brep.edges.size(), -1)};
    bool moved = false;
    for (int round = 0; round < kRounds; ++round) {
        bool any = false;
        for (const auto& c : ConstrainedTriangulation::conflicts(d.scaled, d.keys, d.segments)) {
            const Move m = sep.choose(c);
            if (m.point < 0) continue;
            sep.move(m);
            any = true;
        }
        if (!any) break;
        moved = true;
    }
    return moved;
}

} // namespace seamless
