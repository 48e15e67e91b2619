// SPDX-License-Identifier: MIT
#include <tessellate/trimmed/brep_builder.h>

#include <cmath>

namespace seamless::test {

namespace {

const double kW = std::sqrt(0.5); // a quarter arc's middle weight

} // namespace

BSplineCurve nurbs_line(Vec3 a, Vec3 b) {
    BSplineCurve c;
    c.degree = 1;
    c.knots = {0, 0, 1, 1};
    c.points = {a, b};
    return c;
}

BSplineCurve nurbs_circle(Vec3 c, double r, Vec3 a, Vec3 b) {
    BSplineCurve k;
    k.degree = 2;
    k.knots = {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4};
    const double xs[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1};
    const double ys[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
    for (int i = 0; i < 9; ++i) {
        k.points.push_back(c + r * xs[i] * a + r * ys[i] * b);
        k.weights.push_back(i % 2 ? kW : 1.0);
    }
    return k;
}

BSplineCurve nurbs_half_circle(Vec3 c, double r, Vec3 a, Vec3 b) {
    BSplineCurve k;
    k.degree = 2;
    k.knots = {0, 0, 0, 1, 1, 2, 2, 2};
    const double xs[5] = {0, 1, 1, 1, 0};
    const double ys[5] = {-1, -1, 0, 1, 1};
    for (int i = 0; i < 5; ++i) {
        k.points.push_back(c + r * xs[i] * a + r * ys[i] * b);
        k.weights.push_back(i % 2 ? kW : 1.0);
    }
    return k;
}

BSplineCurve nurbs_conic(Vec3 a, Vec3 m, Vec3 b, double w) {
    BSplineCurve k;
    k.degree = 2;
    k.knots = {0, 0, 0, 1, 1, 1};
    k.points = {a, m, b};
    k.weights = {1, w, 1};
    return k;
}

BSplineSurface PlaneFrame::surface(double u0, double u1, double v0, double v1) const {
    BSplineSurface s;
    s.degree_u = s.degree_v = 1;
    s.size_u = s.size_v = 2;
    s.knots_u = {u0, u0, u1, u1};
    s.knots_v = {v0, v0, v1, v1};
    s.points = {o + u0 * ex + v0 * ey, o + u0 * ex + v1 * ey, o + u1 * ex + v0 * ey,
                o + u1 * ex + v1 * ey};
    return s;
}

BSplineCurve PlaneFrame::pcurve(const BSplineCurve& c) const {
    BSplineCurve p = c;
    for (Vec3& q : p.points) q = uv(q);
    return p;
}

namespace {

// The revolution of profile points (radius, z) about the z axis through
// `base`, with the profile's knots and weights along v.
BSplineSurface revolution(Vec3 base, const BSplineCurve& profile) {
    const BSplineCurve circle = nurbs_circle({}, 1, {1, 0, 0}, {0, 1, 0});
    BSplineSurface s;
    s.degree_u = 2;
    s.degree_v = profile.degree;
    s.size_u = circle.size();
    s.size_v = profile.size();
    s.knots_u = circle.knots;
    s.knots_v = profile.knots;
    for (int i = 0; i < circle.size(); ++i)
        for (int j = 0; j < profile.size(); ++j) {
            const Vec3 q = profile.points[j];
            s.points.push_back(base +
                               Vec3{q.x * circle.points[i].x, q.x * circle.points[i].y, q.z});
            s.weights.push_back(circle.weight(i) * profile.weight(j));
        }
    return s;
}

} // namespace

BSplineSurface cylinder_surface(Vec3 base, double r, double h) {
    return revolution(base, nurbs_line({r, 0, 0}, {r, 0, h}));
}
BSplineSurface cone_surface(Vec3 base, double r, double h) {
    return revolution(base, nurbs_line({r, 0, 0}, {0, 0, h}));
}
BSplineSurface sphere_surface(Vec3 c, double r) {
    return revolution(c, nurbs_half_circle({}, r, {1, 0, 0}, {0, 0, 1}));
}
BSplineSurface torus_surface(Vec3 c, double major, double minor) {
    return revolution(c, nurbs_circle({major, 0, 0}, minor, {1, 0, 0}, {0, 0, 1}));
}

int BRepBuilder::vertex(Vec3 p) {
    m.brep.vertices.push_back({p, 1e-9});
    return static_cast<int>(m.brep.vertices.size()) - 1;
}

int BRepBuilder::surface(BSplineSurface s, const std::string& name) {
    s.name = name;
    m.surfaces.push_back(std::move(s));
    return static_cast<int>(m.surfaces.size()) - 1;
}

int BRepBuilder::edge(const BSplineCurve& c, int start, int end, double tolerance) {
    m.brep.curves.push_back(c);
    BRepEdge e;
    e.curve = static_cast<int>(m.brep.curves.size()) - 1;
    e.t0 = c.t_min(), e.t1 = c.t_max();
    e.start = start, e.end = end;
    e.tolerance = tolerance;
    m.brep.edges.push_back(e);
    return static_cast<int>(m.brep.edges.size()) - 1;
}

int BRepBuilder::degenerate_edge(int vertex, double t0, double t1) {
    BRepEdge e;
    e.t0 = t0, e.t1 = t1;
    e.start = e.end = vertex;
    m.brep.edges.push_back(e);
    return static_cast<int>(m.brep.edges.size()) - 1;
}

void BRepBuilder::use(int edge, bool reversed, const BSplineCurve& pcurve) {
    m.brep.pcurves.push_back(pcurve);
    loops.back().coedges.push_back({edge, reversed, static_cast<int>(m.brep.pcurves.size()) - 1});
}

int BRepBuilder::face(int surface, bool reversed, const std::string& name) {
    BRepFace f;
    f.surface = surface;
    f.reversed = reversed;
    f.loops = std::move(loops);
    f.name = name;
    loops.clear();
    m.brep.faces.push_back(std::move(f));
    return static_cast<int>(m.brep.faces.size()) - 1;
}

Model BRepBuilder::finish(bool closed, const std::string& name) {
    BRepShell shell;
    for (size_t f = 0; f < m.brep.faces.size(); ++f) shell.faces.push_back(static_cast<int>(f));
    shell.closed = closed;
    m.brep.shells.push_back(shell);
    if (closed) m.brep.solids.push_back({{0}, name});
    m.source = name;
    return m;
}

} // namespace seamless::test
