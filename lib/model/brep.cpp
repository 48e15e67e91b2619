// SPDX-License-Identifier: MIT
// validate_brep: the conventions of brep.h, checked on a B-rep that a reader
// made (docs/formats.md, "Model: JSON, version 2 (B-rep)", lists the rules
// and their messages).
#include <seamless/model/model.h>

#include <seamless/base/error.h>

#include <algorithm>
#include <cfloat>
#include <charconv>
#include <cmath>

namespace seamless {
namespace {

// Parameter slack, relative to the width of a domain: an edge's range may
// pass its curve's and pcurves' domains by this much (rounding in the
// files' conversions), not more.
constexpr double kDomainSlack = 1e-6;
// A pcurve may pass its surface's (u,v) domain by this fraction of the
// domain's width: CAD files' pcurves end a little outside their surfaces
// (most by their tolerance, one corpus face by 0.15 %). The tessellator
// extends the surface by its tangent plane there, and the reader's gap check
// measures the clamped surface against the edge's curve.
constexpr double kSurfaceSlack = 1e-2;
// Consecutive pcurves of a loop meet within this fraction of the diagonal of
// their surface's (u,v) domain (or within the vertex's tolerance in 3D, below).
constexpr double kLoopGap = 1e-6;
// Points of a pcurve tested against its surface's domain per knot span.
constexpr int kSamplesPerSpan = 4;

std::string fmt(double x) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, x);
    return std::string(buf, r.ptr);
}

// "(u, v)" and "[a, b]" (appended: GCC 12's -Wrestrict misfires on "(" + s).
std::string pair_text(double a, double b, const char* open, const char* close) {
    std::string s = open;
    s += fmt(a);
    s += ", ";
    s += fmt(b);
    return s += close;
}

std::string uv_text(Vec3 p) {
    return pair_text(p.x, p.y, "(", ")");
}

std::string range_text(double a, double b) {
    return pair_text(a, b, "[", "]");
}

std::string at(const std::string& list, size_t k) {
    return list + "[" + std::to_string(k) + "]";
}

// The interval [lo, hi] widened by the slack.
bool holds(double lo, double hi, double t0, double t1) {
    const double s =
        kDomainSlack * (hi - lo) + 4 * DBL_EPSILON * std::max(std::abs(lo), std::abs(hi));
    return t0 >= lo - s && t1 <= hi + s;
}

struct Checker {
    const Model& m;
    const BRep& b;
    const std::string& file;
    const ModelLimits& limits;

    [[noreturn]] void fail(const std::string& field, const std::string& message) const {
        throw InputError(file, field, message);
    }

    // `list` in "brep.<field>" (the coedges are counted in "brep.faces").
    void count(size_t n, const char* list, const char* field = nullptr) const {
        if (static_cast<long long>(n) > limits.max_brep_items)
            fail(std::string("brep.") + (field ? field : list),
                 std::to_string(n) + " " + list + " exceed the limit of " +
                     std::to_string(limits.max_brep_items));
    }

    // Fields are named only on failure: no string is built per item that passes.
    [[noreturn]] void bad_index(long long i, size_t n, const std::string& field,
                                const char* list) const {
        fail(field, n == 0 ? "index " + std::to_string(i) + " but there are no " + list
                           : "index " + std::to_string(i) + " out of range 0.." +
                                 std::to_string(n - 1) + " (" + list + ")");
    }
    template <class Field> void index(long long i, size_t n, Field field, const char* list) const {
        if (i < 0 || i >= static_cast<long long>(n)) bad_index(i, n, field(), list);
    }

    template <class Field> void tolerance(double t, Field field) const {
        if (!std::isfinite(t) || t < 0 || t > kMaxCoordinate)
            fail(field(), "tolerance " + fmt(t) + " is not a number in 0.." + fmt(kMaxCoordinate));
    }

    void sizes() const {
        count(b.vertices.size(), "vertices");
        count(b.curves.size(), "curves");
        count(b.pcurves.size(), "pcurves");
        count(b.edges.size(), "edges");
        count(b.faces.size(), "faces");
        count(b.shells.size(), "shells");
        count(b.solids.size(), "solids");
        size_t coedges = 0;
        for (const BRepFace& f : b.faces)
            for (const BRepLoop& l : f.loops) coedges += l.coedges.size();
        count(coedges, "coedges", "faces");
    }

    void vertices() const {
        for (size_t k = 0; k < b.vertices.size(); ++k) {
            const auto f = [k](const char* member) { return at("brep.vertices", k) + member; };
            const Vec3 p = b.vertices[k].point;
            for (int i = 0; i < 3; ++i)
                if (!std::isfinite(p[i]) || std::abs(p[i]) > kMaxCoordinate)
                    fail(at(f(".point"), i),
                         "coordinate " + fmt(p[i]) + " is not a finite number within " +
                             fmt(kMaxCoordinate) + " (docs/formats.md, Limits)");
            tolerance(b.vertices[k].tolerance, [&] { return f(".tolerance"); });
        }
    }

    void curves() const {
        for (size_t k = 0; k < b.curves.size(); ++k)
            validate_curve(b.curves[k], file, at("brep.curves", k), limits.max_curve_points);
        for (size_t k = 0; k < b.pcurves.size(); ++k) {
            const std::string f = at("brep.pcurves", k);
            validate_curve(b.pcurves[k], file, f, limits.max_curve_points);
            for (size_t i = 0; i < b.pcurves[k].points.size(); ++i)
                if (b.pcurves[k].points[i].z != 0)
                    fail(at(f + ".points", i),
                         "a pcurve's point is (u, v, 0), got z = " + fmt(b.pcurves[k].points[i].z));
        }
    }

    void edges() const {
        for (size_t k = 0; k < b.edges.size(); ++k) {
            const BRepEdge& e = b.edges[k];
            const auto f = [k](const char* member) {
                return [k, member] { return at("brep.edges", k) + member; };
            };
            if (e.curve != -1) index(e.curve, b.curves.size(), f(".curve"), "curves");
            index(e.start, b.vertices.size(), f(".vertices[0]"), "vertices");
            index(e.end, b.vertices.size(), f(".vertices[1]"), "vertices");
            const auto range = [&] { return range_text(e.t0, e.t1); };
            if (!(std::abs(e.t0) <= kMaxCoordinate && std::abs(e.t1) <= kMaxCoordinate))
                fail(f(".range")(), range() + " is not finite within " + fmt(kMaxCoordinate));
            if (!(e.t0 < e.t1)) fail(f(".range")(), range() + ": t0 must be below t1");
            if (e.degenerate() && e.start != e.end)
                fail(f(".vertices")(), "a degenerate edge (no curve) starts and ends at one "
                                       "vertex, got " +
                                           std::to_string(e.start) + " and " +
                                           std::to_string(e.end));
            if (!e.degenerate()) {
                const BSplineCurve& c = b.curves[e.curve];
                if (!holds(c.t_min(), c.t_max(), e.t0, e.t1))
                    fail(f(".range")(), range() + " is not inside the domain " +
                                            range_text(c.t_min(), c.t_max()) + " of curve " +
                                            std::to_string(e.curve));
            }
            tolerance(e.tolerance, f(".tolerance"));
        }
    }

    // A shell's faces or a solid's shells: at least one, each an index below n.
    void references(const std::vector<int>& v, size_t n, const std::string& f, const char* list,
                    const char* one) const {
        if (v.empty()) fail(f, std::string("expected at least one ") + one);
        for (size_t i = 0; i < v.size(); ++i)
            index(
                v[i], n, [&] { return at(f, i); }, list);
    }

    void shells_and_solids() const {
        for (size_t k = 0; k < b.shells.size(); ++k)
            references(b.shells[k].faces, b.faces.size(), at("brep.shells", k) + ".faces", "faces",
                       "face");
        for (size_t k = 0; k < b.solids.size(); ++k)
            references(b.solids[k].shells, b.shells.size(), at("brep.solids", k) + ".shells",
                       "shells", "shell");
    }
};

// A coedge's pcurve and where it is used from, for the once-per-pcurve check
// of its (u,v) points against the surface's domain (a pcurve shared by many
// coedges is sampled once, over the union of their ranges).
// Where a coedge is, named only when a message needs it.
struct CoedgeAt {
    size_t face = 0, loop = 0, coedge = 0;
    std::string loop_field() const { return at(at("brep.faces", face) + ".loops", loop); }
    std::string field(const char* member = "") const {
        return at(loop_field() + ".coedges", coedge) + member;
    }
};

struct PcurveUse {
    int surface = -1;
    double t0 = 0, t1 = 0;
    CoedgeAt first; // the first coedge using it
};

// Where a coedge starts and ends, in the loop's direction: vertices and
// (u,v) points.
struct CoedgeEnds {
    int v0, v1;
    Vec3 uv0, uv1;
};

CoedgeEnds ends(const BRep& b, const BRepCoedge& c) {
    const BRepEdge& e = b.edges[c.edge];
    const BSplineCurve& p = b.pcurves[c.pcurve];
    CoedgeEnds r{e.start, e.end, evaluate_point(p, e.t0), evaluate_point(p, e.t1)};
    if (c.reversed) {
        std::swap(r.v0, r.v1);
        std::swap(r.uv0, r.uv1);
    }
    return r;
}

// Whether the (u,v) gap from a to z, where two pcurves of a loop meet at
// vertex v, closes: it is within kLoopGap of the surface's domain diagonal,
// or the straight (u,v) segment across it maps, at its ends and three inner
// points, within `tol` of the vertex (a gap along a pole, or within the
// file's tolerances where a surface's metric is large). A gap across a
// periodic surface's seam maps far from the vertex in its middle.
bool gap_closes(const BSplineSurface& s, const Vec3& a, const Vec3& z, const Vec3& v, double tol) {
    const double diag = std::hypot(s.u_max() - s.u_min(), s.v_max() - s.v_min());
    if (distance(z, a) <= kLoopGap * diag) return true;
    for (int i = 0; i <= 4; ++i) {
        const Vec3 uv = a + (z - a) * (i / 4.0);
        if (!(distance(evaluate_point(s, uv.x, uv.y), v) <= tol)) return false;
    }
    return true;
}

// True when s's first and last control columns (in u) or rows (in v)
// coincide: a periodic surface in its NURBS form, on which pcurves may cross
// the seam (the tessellator wraps them).
bool closed_in(const BSplineSurface& s, bool in_u) {
    const double tiny = 1e-12 * control_box(s).max_extent();
    const int n = in_u ? s.size_v : s.size_u;
    for (int k = 0; k < n; ++k) {
        const double gap = in_u ? distance(s.point(0, k), s.point(s.size_u - 1, k))
                                : distance(s.point(k, 0), s.point(k, s.size_v - 1));
        if (!(gap <= tiny)) return false;
    }
    return true;
}

// The (u,v) points of pcurve c over [t0, t1] against surface s's domain:
// the first point outside it (with kSurfaceSlack; a closed direction is
// not bounded), or nothing.
bool leaves_domain(const BSplineCurve& c, double t0, double t1, const BSplineSurface& s,
                   Vec3& out) {
    const double su = closed_in(s, true) ? INFINITY : kSurfaceSlack * (s.u_max() - s.u_min());
    const double sv = closed_in(s, false) ? INFINITY : kSurfaceSlack * (s.v_max() - s.v_min());
    for (int k = c.degree; k < c.size(); ++k) {
        const double a = std::max(t0, c.knots[k]), z = std::min(t1, c.knots[k + 1]);
        if (!(a <= z)) continue;
        for (int i = 0; i <= kSamplesPerSpan; ++i) {
            const Vec3 p = evaluate_point(c, a + (z - a) * i / kSamplesPerSpan);
            if (!(p.x >= s.u_min() - su && p.x <= s.u_max() + su && p.y >= s.v_min() - sv &&
                  p.y <= s.v_max() + sv)) {
                out = p;
                return true;
            }
        }
    }
    return false;
}

// The faces' loops: indices, ranges, chains in 3D and in (u,v), seams, and
// which edges and pcurves they use.
struct LoopChecker {
    const Checker& ck;
    std::vector<char> used;             // per edge: a face uses it
    std::vector<int> face_of, uses;     // per edge: the last face using it, its uses there
    std::vector<char> reversed_first;   // per edge: `reversed` of that face's first use
    std::vector<PcurveUse> pcurve_uses; // per pcurve

    explicit LoopChecker(const Checker& c)
        : ck(c), used(c.b.edges.size(), 0), face_of(c.b.edges.size(), -1),
          uses(c.b.edges.size(), 0), reversed_first(c.b.edges.size(), 0),
          pcurve_uses(c.b.pcurves.size()) {}

    void coedge(const BRepCoedge& c, int surface, const CoedgeAt& where) {
        const BRep& b = ck.b;
        const auto f = [&](const char* member) {
            return [&where, member] { return where.field(member); };
        };
        ck.index(c.edge, b.edges.size(), f(".edge"), "edges");
        ck.index(c.pcurve, b.pcurves.size(), f(".pcurve"), "pcurves");
        const BRepEdge& e = b.edges[c.edge];
        const BSplineCurve& p = b.pcurves[c.pcurve];
        if (!holds(p.t_min(), p.t_max(), e.t0, e.t1))
            ck.fail(where.field(".pcurve"),
                    "the domain " + range_text(p.t_min(), p.t_max()) + " of pcurve " +
                        std::to_string(c.pcurve) + " does not hold the range " +
                        range_text(e.t0, e.t1) + " of edge " + std::to_string(c.edge));
        used[c.edge] = 1;
        const int face = static_cast<int>(where.face);
        if (face_of[c.edge] != face) {
            face_of[c.edge] = face;
            uses[c.edge] = 1;
            reversed_first[c.edge] = c.reversed;
        } else if (++uses[c.edge] > 2) {
            ck.fail(where.field(".edge"),
                    "edge " + std::to_string(c.edge) +
                        " used a third time by this face (a seam is used twice)");
        } else if (bool(reversed_first[c.edge]) == c.reversed) {
            ck.fail(where.field(".edge"), "edge " + std::to_string(c.edge) +
                                              " used twice by this face in the same direction "
                                              "(a seam's two coedges run opposite ways)");
        }
        PcurveUse& u = pcurve_uses[c.pcurve];
        if (u.surface < 0) {
            u = {surface, e.t0, e.t1, where};
        } else if (u.surface != surface) {
            ck.fail(where.field(".pcurve"),
                    "pcurve " + std::to_string(c.pcurve) + " lies on surface " +
                        std::to_string(u.surface) + " (" + u.first.field() +
                        "), not on this face's surface " + std::to_string(surface));
        } else {
            u.t0 = std::min(u.t0, e.t0);
            u.t1 = std::max(u.t1, e.t1);
        }
    }

    // Consecutive coedges share a vertex and their pcurves meet.
    void chain(const BRepLoop& loop, const BSplineSurface& s, CoedgeAt where) const {
        const BRep& b = ck.b;
        const size_t n = loop.coedges.size();
        for (size_t c = 0; c < n; ++c) {
            const BRepCoedge& x = loop.coedges[c];
            const BRepCoedge& y = loop.coedges[(c + 1) % n];
            const CoedgeEnds ex = ends(b, x), ey = ends(b, y);
            where.coedge = (c + 1) % n;
            const auto prev = [c] { return "coedges[" + std::to_string(c) + "]"; };
            if (ex.v1 != ey.v0)
                ck.fail(where.field(), "starts at vertex " + std::to_string(ey.v0) + " but " +
                                           prev() + " ends at vertex " + std::to_string(ex.v1) +
                                           ": the loop is not a closed chain");
            const BRepVertex& v = b.vertices[ey.v0];
            const double tol =
                v.tolerance + std::max(b.edges[x.edge].tolerance, b.edges[y.edge].tolerance);
            if (!gap_closes(s, ex.uv1, ey.uv0, v.point, tol))
                ck.fail(where.field(".pcurve"),
                        "starts at " + uv_text(ey.uv0) + ", " + fmt(distance(ey.uv0, ex.uv1)) +
                            " from the end " + uv_text(ex.uv1) + " of " + prev() +
                            "'s pcurve: the loop is open in (u,v)");
        }
    }

    void face(size_t k) {
        const BRepFace& face = ck.b.faces[k];
        const auto f = [k](const char* member) { return at("brep.faces", k) + member; };
        ck.index(
            face.surface, ck.m.surfaces.size(), [&] { return f(".surface"); }, "surfaces");
        if (face.loops.empty()) ck.fail(f(".loops"), "expected at least one loop (the outer loop)");
        for (size_t l = 0; l < face.loops.size(); ++l) {
            const BRepLoop& loop = face.loops[l];
            CoedgeAt where{k, l, 0};
            if (loop.coedges.empty())
                ck.fail(where.loop_field() + ".coedges", "expected at least one coedge");
            for (size_t c = 0; c < loop.coedges.size(); ++c) {
                where.coedge = c;
                coedge(loop.coedges[c], face.surface, where);
            }
            chain(loop, ck.m.surfaces[face.surface], where);
        }
    }

    // After every face: unused edges, pcurves outside their surfaces.
    void finish() const {
        const BRep& b = ck.b;
        for (size_t e = 0; e < b.edges.size(); ++e)
            if (!used[e]) ck.fail(at("brep.edges", e), "used by no face");
        for (size_t k = 0; k < b.pcurves.size(); ++k) {
            const PcurveUse& u = pcurve_uses[k];
            if (u.surface < 0) continue;
            const BSplineSurface& s = ck.m.surfaces[u.surface];
            Vec3 p;
            if (leaves_domain(b.pcurves[k], u.t0, u.t1, s, p))
                ck.fail(u.first.field(".pcurve"),
                        "pcurve " + std::to_string(k) + " leaves the (u,v) domain " +
                            range_text(s.u_min(), s.u_max()) + " x " +
                            range_text(s.v_min(), s.v_max()) + " of surface " +
                            std::to_string(u.surface) + " at " + uv_text(p));
        }
    }
};

} // namespace

void validate_brep(const Model& m, const std::string& file, const ModelLimits& limits) {
    const Checker ck{m, m.brep, file, limits};
    ck.sizes();
    ck.vertices();
    ck.curves();
    ck.edges();
    LoopChecker loops(ck);
    for (size_t k = 0; k < m.brep.faces.size(); ++k) loops.face(k);
    loops.finish();
    ck.shells_and_solids();
}

} // namespace seamless
