// SPDX-License-Identifier: MIT
#include <tessellate/trimmed/brep_builder.h>
#include <tessellate/trimmed/brep_cases.h>

#include <seamless/tessellate/trimmed/brep_tessellation.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace seamless::test {

namespace {

constexpr Vec3 kX{1, 0, 0}, kY{0, 1, 0}, kZ{0, 0, 1};

// The xy plane z = 0 over [lo, hi]^2.
const PlaneFrame kXY{{0, 0, 0}, kX, kY};

double plane_distance(Vec3 p) {
    return std::abs(p.z);
}

// A free circular hole: one closed edge from c + r a.
void add_hole(BRepBuilder& b, const PlaneFrame& f, Vec3 c, double r, Vec3 a, Vec3 bb, int start) {
    const BSplineCurve circle = nurbs_circle(c, r, a, bb);
    const int v = start >= 0 ? start : b.vertex(c + r * a);
    const int e = b.edge(circle, v, v);
    b.new_loop();
    b.use(e, true, f.pcurve(circle));
}

// A closed polygon loop through vertices, with line edges.
void add_polygon(BRepBuilder& b, const PlaneFrame& f, const std::vector<int>& vs) {
    b.new_loop();
    for (size_t i = 0; i < vs.size(); ++i) {
        const Vec3 p = b.m.brep.vertices[vs[i]].point,
                   q = b.m.brep.vertices[vs[(i + 1) % vs.size()]].point;
        const BSplineCurve line = nurbs_line(p, q);
        const int e = b.edge(line, vs[i], vs[(i + 1) % vs.size()]);
        b.use(e, false, f.pcurve(line));
    }
}

std::vector<int> square_vertices(BRepBuilder& b) {
    return {b.vertex({0, 0, 0}), b.vertex({1, 0, 0}), b.vertex({1, 1, 0}), b.vertex({0, 1, 0})};
}

} // namespace

BRepCase plate_with_holes(int holes) {
    BRepBuilder b;
    const int s = b.surface(kXY.surface(-0.1, 1.1, -0.1, 1.1), "plane");
    add_polygon(b, kXY, square_vertices(b));
    const std::array<Vec3, 4> centres{
        Vec3{0.25, 0.25, 0}, {0.7, 0.3, 0}, {0.3, 0.72, 0}, {0.72, 0.75, 0}};
    for (int h = 0; h < holes; ++h) add_hole(b, kXY, centres[h], 0.12, kX, kY, -1);
    b.face(s, false, "#plate" + std::to_string(holes));
    return {"plate with " + std::to_string(holes) + " holes", b.finish(false, "plate"), false,
            1 - holes, [](int, Vec3 p) { return plane_distance(p); }};
}

BRepCase plate_beyond_its_plane() {
    BRepBuilder b;
    const int s = b.surface(kXY.surface(0.1, 0.9, 0.2, 0.8), "plane");
    add_polygon(b, kXY, square_vertices(b));
    add_hole(b, kXY, {0.25, 0.25, 0}, 0.12, kX, kY, -1);
    b.face(s, false, "#beyond");
    return {"plate beyond its plane's patch", b.finish(false, "beyond"), false, 0,
            [](int, Vec3 p) { return plane_distance(p); }};
}

BRepCase plate_with_touching_holes() {
    BRepBuilder b;
    const int s = b.surface(kXY.surface(-0.1, 1.1, -0.1, 1.1), "plane");
    const int c0 = b.vertex({0, 0, 0}), t1 = b.vertex({0.3, 0, 0}), c1 = b.vertex({1, 0, 0}),
              t2 = b.vertex({1, 0.6, 0}), c2 = b.vertex({1, 1, 0}), c3 = b.vertex({0, 1, 0});
    add_polygon(b, kXY, {c0, t1, c1, t2, c2, c3});
    add_hole(b, kXY, {0.3, 0.15, 0}, 0.15, -1 * kY, kX, t1);
    add_hole(b, kXY, {0.85, 0.6, 0}, 0.15, kX, kY, t2);
    add_hole(b, kXY, {0.4, 0.7, 0}, 0.1, kX, kY, -1);
    b.face(s, false, "#touching");
    return {"plate with holes touching the outer loop", b.finish(false, "touching"), false, -2,
            [](int, Vec3 p) { return plane_distance(p); }};
}

BRepCase box_solid(double short_edge) {
    BRepBuilder b;
    std::array<int, 8> v; // corner (x, y, z) bits
    for (int i = 0; i < 8; ++i)
        v[i] = b.vertex({double(i & 1), double(i >> 1 & 1), double(i >> 2)});
    // Edges between corners differing in one bit, from the lower index.
    std::vector<std::array<int, 3>> edges; // (a, b, first edge); a split edge has two
    int split_vertex = -1;
    for (int i = 0; i < 8; ++i)
        for (int bit : {1, 2, 4})
            if (!(i & bit)) {
                const Vec3 p = b.m.brep.vertices[v[i]].point,
                           q = b.m.brep.vertices[v[i | bit]].point;
                if (i == 0 && bit == 1 && short_edge > 0) {
                    split_vertex = b.vertex({short_edge, 0, 0});
                    edges.push_back(
                        {i, i | bit,
                         b.edge(nurbs_line(p, {short_edge, 0, 0}), v[i], split_vertex)});
                    b.edge(nurbs_line({short_edge, 0, 0}, q), split_vertex, v[i | bit]);
                } else {
                    edges.push_back({i, i | bit, b.edge(nurbs_line(p, q), v[i], v[i | bit])});
                }
            }
    std::vector<std::pair<Vec3, Vec3>> planes; // (point, outward normal) per surface
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
            const int a1 = 1 << ((axis + 1) % 3), a2 = 1 << ((axis + 2) % 3);
            const int base = side ? 1 << axis : 0;
            Vec3 n{}, ex{}, ey{};
            n[axis] = side ? 1 : -1;
            ex[(axis + 1) % 3] = 1;
            ey[(axis + 2) % 3] = 1;
            const PlaneFrame f{b.m.brep.vertices[v[base]].point, ex, ey};
            const int s = b.surface(f.surface(-0.2, 1.2, -0.2, 1.2), "side");
            planes.push_back({f.o, n});
            const std::array<int, 4> ring{base, base | a1, base | a1 | a2, base | a2};
            b.new_loop();
            for (int k = 0; k < 4; ++k) {
                const int p = ring[k], q = ring[(k + 1) % 4];
                for (const auto& e : edges)
                    if ((e[0] == p && e[1] == q) || (e[0] == q && e[1] == p)) {
                        const bool rev = e[0] != p;
                        const bool split = e[0] == 0 && e[1] == 1 && short_edge > 0;
                        for (int j = 0; j < (split ? 2 : 1); ++j) {
                            const int id = e[2] + (rev && split ? 1 - j : j);
                            b.use(id, rev, f.pcurve(b.m.brep.curves[b.m.brep.edges[id].curve]));
                        }
                    }
            }
            b.face(s, dot(cross(ex, ey), n) < 0, "#box" + std::to_string(2 * axis + side));
        }
    return {
        short_edge > 0 ? "box with a short edge" : "box", b.finish(true, "box"), true, 2,
        [planes](int s, Vec3 p) { return std::abs(dot(p - planes[s].first, planes[s].second)); }};
}

namespace {

// A pcurve a -> b over [0, t1].
BSplineCurve uv_line(Vec3 a, Vec3 b, double t1) {
    BSplineCurve c = nurbs_line(a, b);
    c.knots = {0, 0, t1, t1};
    return c;
}

// The lateral face of a revolution: from the circle edge at v = 0 along the
// seam at u = 4 to the edge at v = vt (reversed) and back down the seam at
// u = 0. Either end edge may be degenerate.
void lateral_loop(BRepBuilder& b, int bottom, int seam, int top, double vt) {
    b.new_loop();
    b.use(bottom, false, uv_line({0, 0, 0}, {4, 0, 0}, 4));
    b.use(seam, false, uv_line({4, 0, 0}, {4, vt, 0}, vt));
    b.use(top, true, uv_line({0, vt, 0}, {4, vt, 0}, 4));
    b.use(seam, true, uv_line({0, 0, 0}, {0, vt, 0}, vt));
}

// A disk at height z bounded by a circle edge.
void disk(BRepBuilder& b, double z, double r, int edge, bool down, const std::string& name) {
    const PlaneFrame f{{0, 0, z}, kX, kY};
    const int s = b.surface(f.surface(-1.2 * r, 1.2 * r, -1.2 * r, 1.2 * r), "disk");
    b.new_loop();
    b.use(edge, false, f.pcurve(nurbs_circle({0, 0, z}, r, kX, kY)));
    b.face(s, down, name);
}

} // namespace

BRepCase cylinder_solid(double scale) {
    BRepBuilder b;
    const double h = 2;
    const int v0 = b.vertex({1, 0, 0}), v1 = b.vertex({1, 0, h});
    const int bottom = b.edge(nurbs_circle({0, 0, 0}, 1, kX, kY), v0, v0);
    const int top = b.edge(nurbs_circle({0, 0, h}, 1, kX, kY), v1, v1);
    const int seam = b.edge(nurbs_line({1, 0, 0}, {1, 0, h}), v0, v1);
    const int s = b.surface(cylinder_surface({}, 1, h), "cylinder");
    lateral_loop(b, bottom, seam, top, 1);
    b.face(s, false, "#lateral");
    disk(b, 0, 1, bottom, true, "#bottom");
    disk(b, h, 1, top, false, "#top");
    Model m = b.finish(true, "cylinder");
    if (scale != 1) scale_lengths(m, scale);
    return {"cylinder x" + std::to_string(scale), m, true, 2, [scale, h](int s, Vec3 p) {
                p = p / scale;
                const double d = s == 0   ? std::abs(std::hypot(p.x, p.y) - 1)
                                 : s == 1 ? std::abs(p.z)
                                          : std::abs(p.z - h);
                return d * scale;
            }};
}

BRepCase cylinder_across_seam() {
    BRepBuilder b;
    // Half the cylinder, from angle 270 to 450 degrees: u in [3, 5] beyond
    // the surface's [0, 4]; the arcs start at -y, a quarter span like u = 3.
    const int a0 = b.vertex({0, -1, 0}), a1 = b.vertex({0, 1, 0}), b0 = b.vertex({0, -1, 1}),
              b1 = b.vertex({0, 1, 1});
    auto arc = [&](double z, int from, int to) {
        const int id = b.edge(nurbs_circle({0, 0, z}, 1, -1 * kY, kX), from, to);
        b.m.brep.edges[id].t1 = 2;
        return id;
    };
    const int bottom = arc(0, a0, a1), top = arc(1, b0, b1);
    const int right = b.edge(nurbs_line({0, 1, 0}, {0, 1, 1}), a1, b1);
    const int left = b.edge(nurbs_line({0, -1, 0}, {0, -1, 1}), a0, b0);
    const int s = b.surface(cylinder_surface({}, 1, 1), "cylinder");
    auto shifted = [](Vec3 a, Vec3 c) {
        BSplineCurve k = nurbs_line(a, c);
        k.knots = {0, 0, 2, 2};
        return k;
    };
    b.new_loop();
    b.use(bottom, false, shifted({3, 0, 0}, {5, 0, 0}));
    b.use(right, false, nurbs_line({5, 0, 0}, {5, 1, 0}));
    b.use(top, true, shifted({3, 1, 0}, {5, 1, 0}));
    b.use(left, true, nurbs_line({3, 0, 0}, {3, 1, 0}));
    b.face(s, false, "#across");
    return {"cylinder patch across the seam", b.finish(false, "across"), false, 1,
            [](int, Vec3 p) { return std::abs(std::hypot(p.x, p.y) - 1); }};
}

BRepCase cone_solid() {
    BRepBuilder b;
    const double h = 1.5;
    const int v0 = b.vertex({1, 0, 0}), apex = b.vertex({0, 0, h});
    const int base = b.edge(nurbs_circle({0, 0, 0}, 1, kX, kY), v0, v0);
    const int seam = b.edge(nurbs_line({1, 0, 0}, {0, 0, h}), v0, apex);
    const int tip = b.degenerate_edge(apex, 0, 4);
    const int s = b.surface(cone_surface({}, 1, h), "cone");
    lateral_loop(b, base, seam, tip, 1);
    b.face(s, false, "#cone");
    disk(b, 0, 1, base, true, "#base");
    return {"cone", b.finish(true, "cone"), true, 2, [h](int s, Vec3 p) {
                if (s == 1) return std::abs(p.z);
                return std::abs(h * std::hypot(p.x, p.y) + p.z - h) / std::hypot(h, 1.0);
            }};
}

BRepCase sphere_solid() {
    BRepBuilder b;
    const int south = b.vertex({0, 0, -1}), north = b.vertex({0, 0, 1});
    const int s_pole = b.degenerate_edge(south, 0, 4);
    const int seam = b.edge(nurbs_half_circle({}, 1, kX, kZ), south, north);
    const int n_pole = b.degenerate_edge(north, 0, 4);
    const int s = b.surface(sphere_surface({}, 1), "sphere");
    lateral_loop(b, s_pole, seam, n_pole, 2);
    b.face(s, false, "#sphere");
    return {"sphere", b.finish(true, "sphere"), true, 2,
            [](int, Vec3 p) { return std::abs(norm(p) - 1); }};
}

BRepCase torus_solid() {
    BRepBuilder b;
    const double R = 2, r = 0.5;
    const int v = b.vertex({R + r, 0, 0});
    const int major = b.edge(nurbs_circle({}, R + r, kX, kY), v, v);
    const int minor = b.edge(nurbs_circle({R, 0, 0}, r, kX, kZ), v, v);
    const int s = b.surface(torus_surface({}, R, r), "torus");
    b.new_loop();
    b.use(major, false, uv_line({0, 0, 0}, {4, 0, 0}, 4));
    b.use(minor, false, uv_line({4, 0, 0}, {4, 4, 0}, 4));
    b.use(major, true, uv_line({0, 4, 0}, {4, 4, 0}, 4));
    b.use(minor, true, uv_line({0, 0, 0}, {0, 4, 0}, 4));
    b.face(s, false, "#torus");
    return {"torus", b.finish(true, "torus"), true, 0, [R, r](int, Vec3 p) {
                return std::abs(std::hypot(std::hypot(p.x, p.y) - R, p.z) - r);
            }};
}

BRepCase freeform_face() {
    // Control points at (i/3, j/3): u = x and v = y (linear precision).
    const double h[4][4] = {
        {0, 0.2, -0.1, 0}, {0.1, 0.5, 0.4, -0.2}, {-0.2, 0.3, 0.6, 0.1}, {0, -0.1, 0.2, 0}};
    BSplineSurface bump;
    bump.knots_u = bump.knots_v = {0, 0, 0, 0, 1, 1, 1, 1};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) bump.points.push_back({i / 3.0, j / 3.0, h[i][j]});
    BRepBuilder b;
    const int s = b.surface(bump, "bump");
    const double lo = 0.2, hi = 0.8;
    // The iso-curve of the net at u = u0 (along v; dir 1: at v = u0, along u).
    auto iso = [&](double u0, int dir) {
        const double bern[4] = {(1 - u0) * (1 - u0) * (1 - u0), 3 * u0 * (1 - u0) * (1 - u0),
                                3 * u0 * u0 * (1 - u0), u0 * u0 * u0};
        BSplineCurve c;
        c.degree = 3;
        c.knots = bump.knots_u;
        for (int j = 0; j < 4; ++j) {
            Vec3 q{};
            for (int i = 0; i < 4; ++i) q += bern[i] * (dir ? bump.point(j, i) : bump.point(i, j));
            c.points.push_back(q);
        }
        return c;
    };
    const int c00 = b.vertex(evaluate(bump, lo, lo).point),
              c10 = b.vertex(evaluate(bump, hi, lo).point),
              c11 = b.vertex(evaluate(bump, hi, hi).point),
              c01 = b.vertex(evaluate(bump, lo, hi).point);
    auto edge = [&](const BSplineCurve& c, int from, int to) {
        const int id = b.edge(c, from, to);
        b.m.brep.edges[id].t0 = lo;
        b.m.brep.edges[id].t1 = hi;
        return id;
    };
    const int bottom = edge(iso(lo, 1), c00, c10), right = edge(iso(hi, 0), c10, c11),
              top = edge(iso(hi, 1), c01, c11), left = edge(iso(lo, 0), c00, c01);
    b.new_loop();
    b.use(bottom, false, nurbs_line({0, lo, 0}, {1, lo, 0}));
    b.use(right, false, nurbs_line({hi, 0, 0}, {hi, 1, 0}));
    b.use(top, true, nurbs_line({0, hi, 0}, {1, hi, 0}));
    b.use(left, true, nurbs_line({lo, 0, 0}, {lo, 1, 0}));
    b.face(s, false, "#bump");
    // The distance to the tangent plane at (x, y, f(x, y)): to first order the
    // distance to the surface.
    return {"freeform face", b.finish(false, "bump"), false, 1, [bump](int, Vec3 p) {
                const SurfacePoint s = evaluate(bump, p.x, p.y);
                return std::abs(dot(p - s.point, normalize(s.normal())));
            }};
}

BRepCase sliver_face(double height) {
    BRepBuilder b;
    const int s = b.surface(kXY.surface(-0.1, 1.1, -0.1, 0.1), "plane");
    const int a = b.vertex({0, 0, 0}), c = b.vertex({1, 0, 0});
    const BSplineCurve line = nurbs_line({0, 0, 0}, {1, 0, 0});
    const BSplineCurve arc = nurbs_conic({0, 0, 0}, {0.5, 2 * height, 0}, {1, 0, 0}, 1);
    const int e0 = b.edge(line, a, c), e1 = b.edge(arc, a, c);
    b.new_loop();
    b.use(e0, false, kXY.pcurve(line));
    b.use(e1, true, kXY.pcurve(arc));
    b.face(s, false, "#sliver");
    return {"sliver face", b.finish(false, "sliver"), false, 1,
            [](int, Vec3 p) { return plane_distance(p); }};
}

BRepCase crossing_loops() {
    BRepBuilder b;
    const int s = b.surface(kXY.surface(-0.1, 1.5, -0.1, 1.1), "plane");
    add_polygon(b, kXY, square_vertices(b));
    add_hole(b, kXY, {1, 0.5, 0}, 0.2, kX, kY, -1);
    b.face(s, false, "#crossing");
    return {"crossing loops", b.finish(false, "crossing"), false, 0,
            [](int, Vec3 p) { return plane_distance(p); }};
}

BRepCase tangent_hole() {
    BRepBuilder b;
    const int s = b.surface(kXY.surface(-0.1, 1.1, -0.1, 1.1), "plane");
    // Both circles start at the top, where they touch with one tangent.
    const int top = b.vertex({0.5, 0.95, 0});
    const BSplineCurve rim = nurbs_circle({0.5, 0.5, 0}, 0.45, kY, -1 * kX);
    b.new_loop();
    b.use(b.edge(rim, top, top), false, kXY.pcurve(rim));
    add_hole(b, kXY, {0.5, 0.75, 0}, 0.2, kY, -1 * kX, top);
    b.face(s, false, "#tangent");
    return {"disk with a tangent hole", b.finish(false, "tangent"), false, 0,
            [](int, Vec3 p) { return plane_distance(p); }};
}

BRepCase bent_plate() {
    BRepBuilder b;
    // u in [0, 1] along x on z = 0, then u in [1, 2] up z at x = 1; v is y.
    BSplineSurface bent;
    bent.degree_u = bent.degree_v = 1;
    bent.size_u = 3;
    bent.size_v = 2;
    bent.knots_u = {0, 0, 1, 2, 2};
    bent.knots_v = {0, 0, 1, 1};
    bent.points = {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}, {1, 0, 1}, {1, 1, 1}};
    const int s = b.surface(bent, "bent");
    // The trimming loop [0.2, 1.8] x [0.2, 0.8]: its edges along u are bent
    // lines with the crease's knot, the same parameter as their pcurves.
    const auto bent_line = [](double y) {
        BSplineCurve c = nurbs_line({0.2, y, 0}, {1, y, 0.8});
        c.knots = {0, 0, 0.8, 1.6, 1.6};
        c.points = {{0.2, y, 0}, {1, y, 0}, {1, y, 0.8}};
        return c;
    };
    const int a = b.vertex({0.2, 0.2, 0}), c = b.vertex({1, 0.2, 0.8}), d = b.vertex({1, 0.8, 0.8}),
              e = b.vertex({0.2, 0.8, 0});
    const BSplineCurve low = bent_line(0.2), high = bent_line(0.8);
    const BSplineCurve up = nurbs_line({1, 0.2, 0.8}, {1, 0.8, 0.8}),
                       back = nurbs_line({0.2, 0.8, 0}, {0.2, 0.2, 0});
    b.new_loop();
    BSplineCurve pl = uv_line({0.2, 0.2, 0}, {1.8, 0.2, 0}, 1.6), ph = pl;
    ph.points = {{0.2, 0.8, 0}, {1.8, 0.8, 0}};
    b.use(b.edge(low, a, c), false, pl);
    b.use(b.edge(up, c, d), false, uv_line({1.8, 0.2, 0}, {1.8, 0.8, 0}, 1));
    b.use(b.edge(high, e, d), true, ph);
    b.use(b.edge(back, e, a), false, uv_line({0.2, 0.8, 0}, {0.2, 0.2, 0}, 1));
    b.face(s, false, "#bent");
    return {"bent plate", b.finish(false, "bent"), false, 1, [](int, Vec3 p) {
                const double flat = p.x <= 1 ? std::abs(p.z) : std::hypot(p.x - 1, p.z);
                const double up = p.z >= 0 ? std::abs(p.x - 1) : std::hypot(p.x - 1, p.z);
                return std::min(flat, up);
            }};
}

std::vector<BRepCase> all_brep_cases() {
    std::vector<BRepCase> c;
    for (int h = 0; h <= 4; ++h) c.push_back(plate_with_holes(h));
    c.push_back(plate_with_touching_holes());
    c.push_back(plate_beyond_its_plane());
    c.push_back(box_solid());
    c.push_back(box_solid(1e-4));
    c.push_back(cylinder_solid());
    c.push_back(cylinder_solid(1e6));
    c.push_back(cylinder_solid(1e-6));
    c.push_back(cylinder_solid(1e150));
    c.push_back(cylinder_solid(1e-150));
    c.push_back(cylinder_across_seam());
    c.push_back(cone_solid());
    c.push_back(sphere_solid());
    c.push_back(torus_solid());
    c.push_back(freeform_face());
    c.push_back(sliver_face(1e-3));
    c.push_back(tangent_hole());
    c.push_back(bent_plate());
    return c;
}

} // namespace seamless::test
