// SPDX-License-Identifier: MIT
#include <seamless/base/segment_distance.h>
#include <seamless/tessellate/trimmed/constrained_triangulation.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <deque>

namespace seamless {

namespace {

struct VertexInfo {
    int index = -1; // point index; -1: not yet numbered
};
struct FaceInfo {
    int nesting = -1; // constraints crossed from the infinite face; -1: not yet marked
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
    Cdt& cdt = impl_->cdt;
    std::vector<Cdt::Vertex_handle> handle(points.size());
    try {
        for (size_t i = 0; i < points.size(); ++i) {
            handle[i] = cdt.insert(Point(points[i].x, points[i].y));
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

void ConstrainedTriangulation::triangles(std::vector<DomainTriangle>& out) const {
    out.clear();
    for (auto f = impl_->cdt.finite_faces_begin(); f != impl_->cdt.finite_faces_end(); ++f) {
        if (f->info().nesting % 2 != 1) continue;
        DomainTriangle t;
        for (int k = 0; k < 3; ++k) {
            t.corners[k] = f->vertex(k)->info().index;
            t.boundary[k] = f->is_constrained(k);
        }
        out.push_back(t);
    }
}

int ConstrainedTriangulation::insert(Vec3 p, double clearance) {
    Cdt& cdt = impl_->cdt;
    const Point q(p.x, p.y);
    Cdt::Locate_type type;
    int li = 0;
    const Cdt::Face_handle f = cdt.locate(q, type, li);
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
    // Every face the insertion made is incident to the new vertex, and lies
    // in the region of the face it fell in (flips do not cross constraints).
    auto c = cdt.incident_faces(v), done = c;
    do {
        c->info().nesting = nesting;
    } while (++c != done);
    return points_++;
}

} // namespace seamless
