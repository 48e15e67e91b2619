// SPDX-License-Identifier: MIT
#include <seamless/base/segment_distance.h>
#include <seamless/tessellate/trimmed/faces/constrained_triangulation.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Intersections_2/Segment_2_Segment_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <deque>
#include <tuple>

namespace seamless {

namespace {

struct VertexInfo {
    int index = -1; // point index; -1: not yet numbered
};
struct FaceInfo {
    int nesting = -1; // constraints crossed from the infinite face; -1: not yet marked
    // set_tag's value and the corners it was set for: CGAL reuses a face
    // object for one of the triangles an insertion or a flip makes.
    int tag = -1;
    std::array<int, 3> tagged{-1, -1, -1};
};

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<VertexInfo, K>;
using Fbi = CGAL::Triangulation_face_base_with_info_2<FaceInfo, K>;
using Fb = CGAL::Constrained_triangulation_face_base_2<K, Fbi>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
// Throws when constraints overlap or a point falls on one: never a
// construction (an intersection point) that would be a vertex of one face's
// side only.
using Cdt =
    CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::No_constraint_intersection_tag>;
using Point = Cdt::Point;

// Marks the faces reachable from `start` without crossing a constraint;
// constraints met are queued for the next nesting level.
void mark_region(Cdt::Face_handle start, int nesting, std::deque<Cdt::Edge>& border) {
    std::deque<Cdt::Face_handle> queue{start};
    while (!queue.empty()) {
        const Cdt::Face_handle f = queue.front();
        queue.pop_front();
        if (f->info().nesting != -1) continue;
        f->info().nesting = nesting;
        for (int i = 0; i < 3; ++i) {
            const Cdt::Face_handle n = f->neighbor(i);
            if (n->info().nesting != -1) continue;
            if (f->is_constrained(i))
                border.push_back({f, i});
            else
                queue.push_back(n);
        }
    }
}

Vec3 vec(const Point& p) {
    return {p.x(), p.y(), 0};
}

} // namespace

struct ConstrainedTriangulation::Impl {
    Cdt cdt;
    // By point index: the start of each point location's walk, which from
    // a near vertex takes a few steps instead of O(sqrt n) (CGAL's locate
    // without a hint starts anywhere).
    std::vector<Cdt::Vertex_handle> vertex;
    std::vector<Cdt::Face_handle> listed; // by the last triangles() list

    void mark_domain() {
        for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info().nesting = -1;
        std::deque<Cdt::Edge> border;
        mark_region(cdt.infinite_face(), 0, border);
        while (!border.empty()) {
            const Cdt::Edge e = border.front();
            border.pop_front();
            const Cdt::Face_handle n = e.first->neighbor(e.second);
            if (n->info().nesting == -1) mark_region(n, e.first->info().nesting + 1, border);
        }
    }
};

ConstrainedTriangulation::ConstrainedTriangulation() : impl_(std::make_unique<Impl>()) {}
ConstrainedTriangulation::~ConstrainedTriangulation() = default;

bool ConstrainedTriangulation::build(const std::vector<Vec3>& points,
                                     const std::vector<std::int64_t>& keys,
                                     const std::vector<std::array<int, 2>>& segments) {
    // Built again after a failure: from nothing.
    if (impl_->cdt.number_of_vertices() > 0) impl_ = std::make_unique<Impl>();
    points_ = 0;
    Cdt& cdt = impl_->cdt;
    std::vector<Cdt::Vertex_handle>& handle = impl_->vertex;
    handle.assign(points.size(), {});
    try {
        for (size_t i = 0; i < points.size(); ++i) {
            // Loop points come in order along their loops: the previous one
            // is near.
            const Cdt::Face_handle near = i > 0 ? handle[i - 1]->face() : Cdt::Face_handle();
            handle[i] = cdt.insert(Point(points[i].x, points[i].y), near);
            int& index = handle[i]->info().index;
            if (index == -1)
                index = static_cast<int>(i);
            else if (keys[index] != keys[i])
                return false;
        }
        for (const auto& s : segments)
            if (handle[s[0]] != handle[s[1]]) cdt.insert_constraint(handle[s[0]], handle[s[1]]);
        // A constraint through a point is split there without an exception.
        Cdt::Face_handle f;
        int i = 0;
        for (const auto& s : segments)
            if (handle[s[0]] != handle[s[1]] && !cdt.is_edge(handle[s[0]], handle[s[1]], f, i))
                return false;
    } catch (const Cdt::Intersection_of_constraints_exception&) {
        return false;
    } catch (const CGAL::Failure_exception&) {
        return false;
    }
    // Loops whose points all lie on one line (a face collapsed in (u,v)) have
    // no triangle: there is no face to mark, and nothing to triangulate.
    if (cdt.dimension() < 2) return false;
    points_ = static_cast<int>(points.size());
    impl_->mark_domain();
    return true;
}

std::vector<ConstrainedTriangulation::Conflict>
ConstrainedTriangulation::conflicts(const std::vector<Vec3>& points,
                                    const std::vector<std::int64_t>& keys,
                                    const std::vector<std::array<int, 2>>& segments) {
    const K::Orientation_2 orientation;
    const auto at = [&](int i) { return Point(points[i].x, points[i].y); };
    // p on the closed segment ab (exact: collinear, then within the box).
    const auto on = [&](const Point& p, const Point& a, const Point& b) {
        return orientation(a, b, p) == CGAL::COLLINEAR &&
               CGAL::collinear_are_ordered_along_line(a, p, b);
    };
    // 0: none; 1: a conflict; 2: an overlap along a length.
    const auto conflict = [&](const std::array<int, 2>& s, const std::array<int, 2>& r) {
        const Point a = at(s[0]), b = at(s[1]), c = at(r[0]), d = at(r[1]);
        const bool collinear =
            orientation(a, b, c) == CGAL::COLLINEAR && orientation(a, b, d) == CGAL::COLLINEAR;
        // Ends at one place: one mesh vertex (the loops meet there) when the
        // keys agree, else two vertices a triangulation cannot tell apart.
        for (int i : s)
            for (int j : r)
                if (at(i) == at(j)) {
                    if (keys[i] != keys[j]) return 1;
                    // Sharing an end, they conflict only where one runs along
                    // the other: its far end on the other segment.
                    const Point far_s = at(i == s[0] ? s[1] : s[0]);
                    const Point far_r = at(j == r[0] ? r[1] : r[0]);
                    return on(far_s, c, d) || on(far_r, a, b) ? 2 : 0;
                }
        const K::Segment_2 ab(a, b), cd(c, d);
        if (!CGAL::do_intersect(ab, cd)) return 0;
        if (!collinear) return 1;
        // Collinear: along a length, or touching at one point.
        const auto x = CGAL::intersection(ab, cd);
        return x && boost::get<K::Segment_2>(&*x) ? 2 : 1;
    };
    // A sweep along x over the segments' boxes.
    std::vector<int> order(segments.size());
    std::vector<double> lo(segments.size()), hi(segments.size());
    for (size_t i = 0; i < segments.size(); ++i) {
        order[i] = static_cast<int>(i);
        lo[i] = std::min(points[segments[i][0]].x, points[segments[i][1]].x);
        hi[i] = std::max(points[segments[i][0]].x, points[segments[i][1]].x);
    }
    std::sort(order.begin(), order.end(), [&](int a, int b) { return lo[a] < lo[b]; });
    std::vector<Conflict> out;
    for (size_t i = 0; i < order.size(); ++i)
        for (size_t j = i + 1; j < order.size() && lo[order[j]] <= hi[order[i]]; ++j) {
            const auto& s = segments[order[i]];
            const auto& r = segments[order[j]];
            if (s[0] == s[1] || r[0] == r[1]) continue;
            if (const int kind = conflict(s, r))
                out.push_back(
                    {std::min(order[i], order[j]), std::max(order[i], order[j]), kind == 2});
        }
    std::sort(out.begin(), out.end(), [](const Conflict& x, const Conflict& y) {
        return std::tie(x.a, x.b) < std::tie(y.a, y.b);
    });
    return out;
}

void ConstrainedTriangulation::triangles(std::vector<DomainTriangle>& out) {
    out.clear();
    impl_->listed.clear();
    for (auto f = impl_->cdt.finite_faces_begin(); f != impl_->cdt.finite_faces_end(); ++f) {
        if (f->info().nesting % 2 != 1) continue;
        DomainTriangle t;
        for (int k = 0; k < 3; ++k) {
            t.corners[k] = f->vertex(k)->info().index;
            t.boundary[k] = f->is_constrained(k);
        }
        // Element by element: std::array's == is a call to memcmp.
        const std::array<int, 3>& was = f->info().tagged;
        if (was[0] == t.corners[0] && was[1] == t.corners[1] && was[2] == t.corners[2])
            t.tag = f->info().tag;
        out.push_back(t);
        impl_->listed.push_back(f);
    }
}

void ConstrainedTriangulation::set_tag(int k, int tag) {
    FaceInfo& info = impl_->listed[k]->info();
    info.tag = tag;
    for (int i = 0; i < 3; ++i) info.tagged[i] = impl_->listed[k]->vertex(i)->info().index;
}

int ConstrainedTriangulation::insert(Vec3 p, double clearance, int near) {
    Cdt& cdt = impl_->cdt;
    const Point q(p.x, p.y);
    Cdt::Locate_type type;
    int li = 0;
    const Cdt::Face_handle f = cdt.locate(q, type, li, impl_->vertex[near]->face());
    if (type != Cdt::FACE || cdt.is_infinite(f) || f->info().nesting % 2 != 1) return kOutside;
    for (int k = 0; k < 3; ++k)
        if (f->is_constrained(k) &&
            point_segment_distance(p, vec(f->vertex(Cdt::ccw(k))->point()),
                                   vec(f->vertex(Cdt::cw(k))->point())) < clearance)
            return kOutside;
    for (int k = 0; k < 3; ++k)
        if (distance(p, vec(f->vertex(k)->point())) < clearance) return kCrowded;
    const int nesting = f->info().nesting;
    const Cdt::Vertex_handle v = cdt.insert(q, f);
    v->info().index = points_;
    impl_->vertex.push_back(v);
    // Every face the insertion made is incident to the new vertex, and lies
    // in the region of the face it fell in (flips do not cross constraints).
    auto c = cdt.incident_faces(v), done = c;
    do {
        c->info().nesting = nesting;
    } while (++c != done);
    return points_++;
}

} // namespace seamless
