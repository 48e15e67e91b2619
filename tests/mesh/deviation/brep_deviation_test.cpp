// SPDX-License-Identifier: MIT
// Two-way deviation of any mesh against a B-rep (lib/mesh/deviation/brep_deviation.h)
// on a hand-built B-rep: a planar square face with a circular hole (a
// rational quadratic NURBS circle) and a whole cylinder with its seam.
#include <seamless/mesh/deviation/brep_deviation.h>
#include <seamless/mesh/deviation/face_region.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace seamless;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kHole = 0.4;              // radius of the hole, centred at the origin
constexpr double kRadius = 0.5;            // of the cylinder
constexpr Vec3 kAxis{3, 0, 0};             // the cylinder's axis: x = 3, y = 0, z in [0, 1]
constexpr int kAround = 256, kAcross = 16; // the meshes' resolution
const double kSagitta = 1 - std::cos(kPi / kAround); // chord error per unit radius

BSplineCurve line(Vec3 a, Vec3 b) {
    return {1, {0, 0, 1, 1}, {a, b}, {}};
}

// Rational quadratic circle of radius r about c in the plane z = c.z, over
// t in [0, 1] (knots at the quarters), starting at angle 0, counter-clockwise.
BSplineCurve circle(Vec3 c, double r) {
    const double w = std::sqrt(0.5);
    BSplineCurve k;
    k.degree = 2;
    k.knots = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
    const double xs[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1}, ys[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
    for (int i = 0; i < 9; ++i) {
        k.points.push_back({c.x + r * xs[i], c.y + r * ys[i], c.z});
        k.weights.push_back(i % 2 ? w : 1);
    }
    return k;
}

// Adds an edge with its 3D curve and one pcurve per use (reversed, pcurve).
int add_edge(BRep& b, BSplineCurve curve, int start, int end) {
    b.curves.push_back(std::move(curve));
    b.edges.push_back({static_cast<int>(b.curves.size()) - 1, 0, 1, start, end, 1e-9});
    return static_cast<int>(b.edges.size()) - 1;
}

BRepCoedge use(BRep& b, int edge, bool reversed, BSplineCurve pcurve) {
    b.pcurves.push_back(std::move(pcurve));
    return {edge, reversed, static_cast<int>(b.pcurves.size()) - 1};
}

// Face 0: the square [-1, 1]^2 at z = 0, u along x and v along y over [0, 1],
// with the hole; face 1: the cylinder, u around (the circle's parameter) and v up.
Model two_faces() {
    Model m;
    m.source = "two_faces";
    BSplineSurface plane;
    plane.degree_u = plane.degree_v = 1;
    plane.size_u = plane.size_v = 2;
    plane.knots_u = plane.knots_v = {0, 0, 1, 1};
    plane.points = {{-1, -1, 0}, {-1, 1, 0}, {1, -1, 0}, {1, 1, 0}};
    BSplineSurface cyl;
    const BSplineCurve around = circle(kAxis, kRadius);
    cyl.degree_u = 2;
    cyl.degree_v = 1;
    cyl.size_u = 9;
    cyl.size_v = 2;
    cyl.knots_u = around.knots;
    cyl.knots_v = {0, 0, 1, 1};
    for (int i = 0; i < 9; ++i)
        for (int j = 0; j < 2; ++j) {
            cyl.points.push_back(around.points[i] + Vec3{0, 0, double(j)});
            cyl.weights.push_back(around.weights[i]);
        }
    m.surfaces = {plane, cyl};

    BRep& b = m.brep;
    const Vec3 corners[4] = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    for (const Vec3& c : corners) b.vertices.push_back({c, 1e-9});
    BRepLoop outer;
    for (int i = 0; i < 4; ++i) {
        const Vec3 a = corners[i], c = corners[(i + 1) % 4];
        const int e = add_edge(b, line(a, c), i, (i + 1) % 4);
        const auto uv = [](Vec3 p) { return Vec3{(p.x + 1) / 2, (p.y + 1) / 2, 0}; };
        outer.coedges.push_back(use(b, e, false, line(uv(a), uv(c))));
    }
    b.vertices.push_back({{kHole, 0, 0}, 1e-9});
    BRepLoop hole;
    const int e_hole = add_edge(b, circle({0, 0, 0}, kHole), 4, 4);
    hole.coedges.push_back(use(b, e_hole, true, circle({0.5, 0.5, 0}, kHole / 2)));
    b.faces.push_back({0, false, {outer, hole}, "square"});

    const Vec3 bottom = kAxis + Vec3{kRadius, 0, 0}, top = bottom + Vec3{0, 0, 1};
    b.vertices.push_back({bottom, 1e-9});
    b.vertices.push_back({top, 1e-9});
    const int e_bottom = add_edge(b, circle(kAxis, kRadius), 5, 5);
    const int e_top = add_edge(b, circle(kAxis + Vec3{0, 0, 1}, kRadius), 6, 6);
    const int e_seam = add_edge(b, line(bottom, top), 5, 6);
    BRepLoop side;
    side.coedges = {use(b, e_bottom, false, line({0, 0, 0}, {1, 0, 0})),
                    use(b, e_seam, false, line({1, 0, 0}, {1, 1, 0})),
                    use(b, e_top, true, line({0, 1, 0}, {1, 1, 0})),
                    use(b, e_seam, true, line({0, 0, 0}, {0, 1, 0}))};
    b.faces.push_back({1, false, {side}, "cylinder"});
    return m;
}

// Point of the square's boundary on the ray from the origin at angle a.
Vec3 on_square(double a) {
    const double c = std::cos(a), s = std::sin(a);
    return Vec3{c, s, 0} / std::max(std::abs(c), std::abs(s));
}

// Quads between the last rows + 1 rings of `cols` vertices each, split in two.
void add_grid(TriangleMesh& mesh, int rows, int cols) {
    const int base = mesh.vertex_count() - (rows + 1) * cols;
    for (int i = 0; i < rows; ++i)
        for (int j = 0; j < cols; ++j) {
            const int a = base + i * cols + j, b = base + i * cols + (j + 1) % cols;
            const int c = a + cols, d = b + cols;
            mesh.triangles.push_back({a, b, d});
            mesh.triangles.push_back({a, d, c});
        }
}

struct MeshShape {
    double lift = 0;         // every vertex moved this far along the outward normal
    bool cover_hole = false; // the square meshed whole, the hole covered
};

// Both faces, vertices on them (lift 0): rings from the hole's circle out to
// the square (or a fan about the centre, then rings), and the cylinder's rings.
TriangleMesh mesh_of(const MeshShape& shape) {
    TriangleMesh mesh;
    const Vec3 lift{0, 0, shape.lift};
    const int first = shape.cover_hole ? 1 : 0;
    if (shape.cover_hole) mesh.positions.push_back(lift);
    for (int i = first; i <= kAcross; ++i)
        for (int j = 0; j < kAround; ++j) {
            const double a = 2 * kPi * j / kAround, s = double(i) / kAcross;
            const Vec3 inner =
                shape.cover_hole ? Vec3{} : kHole * Vec3{std::cos(a), std::sin(a), 0};
            mesh.positions.push_back((1 - s) * inner + s * on_square(a) + lift);
        }
    for (int j = 0; shape.cover_hole && j < kAround; ++j)
        mesh.triangles.push_back({0, 1 + j, 1 + (j + 1) % kAround});
    add_grid(mesh, kAcross - first, kAround);
    for (int i = 0; i <= kAcross; ++i)
        for (int j = 0; j < kAround; ++j) {
            const double a = 2 * kPi * j / kAround, r = kRadius + shape.lift;
            mesh.positions.push_back(kAxis +
                                     Vec3{r * std::cos(a), r * std::sin(a), double(i) / kAcross});
        }
    add_grid(mesh, kAcross, kAround);
    return mesh;
}

BRepDeviationOptions quick() {
    BRepDeviationOptions o;
    o.relative_spacing = 4e-3;
    return o;
}

} // namespace

TEST_CASE("face region: the hole, the square and the cylinder's period", "[brep_deviation]") {
    const Model m = two_faces();
    const FaceRegion square(m, 0, {});
    CHECK(square.contains(0.9, 0.5));
    CHECK(square.contains(0.02, 0.98));
    CHECK_FALSE(square.contains(0.5, 0.5));        // the hole's centre
    CHECK_FALSE(square.contains(0.5 + 0.19, 0.5)); // inside the hole, near its rim
    CHECK(square.contains(0.5 + 0.21, 0.5));
    CHECK_FALSE(square.contains(1.01, 0.5));
    CHECK(square.u0() == Approx(0).margin(1e-12));
    CHECK(square.u1() == Approx(1).margin(1e-12));
    const FaceRegion cyl(m, 1, {});
    CHECK(cyl.contains(0.3, 0.5));
    CHECK(cyl.contains(1.3, 0.5)); // one period off: the same point
    CHECK_FALSE(cyl.contains(0.3, 1.2));
    double u = 1.25, v = 0.5;
    cyl.wrap(u, v);
    CHECK(u == Approx(0.25));
    // A face without loops is its whole surface.
    Model whole = m;
    whole.brep.faces[0].loops.clear();
    const FaceRegion all(whole, 0, {});
    CHECK(all.contains(0.5, 0.5));
    CHECK_FALSE(all.contains(1.5, 0.5));
}

TEST_CASE("brep deviation: a mesh on the faces measures its chords, both ways",
          "[brep_deviation][heavy]") {
    const Model m = two_faces();
    const TriangleMesh mesh = mesh_of({});
    const Deviation d = measure_brep_deviation(m, mesh, quick());
    // The chords of the hole and the cylinder: within kSagitta of the radius.
    const double chord = kSagitta * kRadius * 1.01 + 1e-12;
    INFO("face->mesh " << d.surface_to_mesh.max << ", mesh->face " << d.mesh_to_surface.max);
    CHECK(d.surface_to_mesh.samples > 10000);
    // Every vertex once, then edge midpoints and centroids per triangle.
    CHECK(d.mesh_to_surface.samples == mesh.vertex_count() + 4LL * mesh.triangle_count());
    CHECK(d.surface_to_mesh.max <= chord);
    CHECK(d.mesh_to_surface.max <= chord);
    CHECK(d.surface_to_mesh.rms <= d.surface_to_mesh.max);
}

TEST_CASE("brep deviation: a mesh lifted by h off the faces measures h both ways",
          "[brep_deviation][heavy]") {
    const Model m = two_faces();
    const double h = 0.01;
    const Deviation d = measure_brep_deviation(m, mesh_of({h, false}), quick());
    INFO("face->mesh " << d.surface_to_mesh.max << ", mesh->face " << d.mesh_to_surface.max);
    CHECK(d.surface_to_mesh.max == Approx(h).epsilon(0.02));
    CHECK(d.mesh_to_surface.max == Approx(h).epsilon(0.02));
    // Nearly every sample is h off: the rms too.
    CHECK(d.surface_to_mesh.rms == Approx(h).epsilon(0.05));
    CHECK(d.mesh_to_surface.rms == Approx(h).epsilon(0.05));
}

TEST_CASE("brep deviation: a mesh covering the hole is far from the faces only there",
          "[brep_deviation][heavy]") {
    const Model m = two_faces();
    const Deviation d = measure_brep_deviation(m, mesh_of({0, true}), quick());
    INFO("face->mesh " << d.surface_to_mesh.max << ", mesh->face " << d.mesh_to_surface.max);
    // Every face point is on the mesh (the cylinder's chords aside) ...
    CHECK(d.surface_to_mesh.max <= kSagitta * kRadius * 1.01 + 1e-12);
    // ... but the hole's centre, a mesh vertex, is the hole's radius from the faces.
    CHECK(d.mesh_to_surface.max == Approx(kHole).epsilon(1e-3));
}

TEST_CASE("brep deviation: the same figures on one and two threads", "[brep_deviation][heavy]") {
    const Model m = two_faces();
    const TriangleMesh mesh = mesh_of({0.003, true});
    BRepDeviationOptions o = quick();
    o.threads = 1;
    const Deviation one = measure_brep_deviation(m, mesh, o);
    o.threads = 2;
    const Deviation two = measure_brep_deviation(m, mesh, o);
    CHECK(one.surface_to_mesh.max == two.surface_to_mesh.max);
    CHECK(one.surface_to_mesh.rms == two.surface_to_mesh.rms);
    CHECK(one.surface_to_mesh.samples == two.surface_to_mesh.samples);
    CHECK(one.mesh_to_surface.max == two.mesh_to_surface.max);
    CHECK(one.mesh_to_surface.rms == two.mesh_to_surface.rms);
    CHECK(one.mesh_to_surface.samples == two.mesh_to_surface.samples);
}

TEST_CASE("brep deviation: a point beside an edge is measured against the edge's faces",
          "[brep_deviation]") {
    // Without face samples to start from (none of the nearest, as where a
    // wall's samples crowd an edge that a large plane's are far from), a
    // point on the square beside the hole is found on the square from the
    // hole's edge samples, not measured against the edge itself.
    const Model m = two_faces();
    BRepDeviationOptions o = quick();
    o.face_neighbours = 0;
    for (double h : {0.0, 0.01}) {
        TriangleMesh mesh;
        mesh.positions = {{kHole + 0.05, -0.02, h}, {kHole + 0.1, 0, h}, {kHole + 0.05, 0.02, h}};
        mesh.triangles = {{0, 1, 2}};
        const Deviation d = measure_brep_deviation(m, mesh, o);
        INFO("lift " << h << ": mesh->face " << d.mesh_to_surface.max);
        CHECK(d.mesh_to_surface.max == Approx(h).margin(1e-12));
        CHECK(d.mesh_to_surface.at.z == h);
    }
}

namespace {

// A planar square face [x0, x0 + size]^2 at height z, (u,v) over [0, 1]^2.
void add_square(Model& m, double x0, double size, double z) {
    BSplineSurface plane;
    plane.degree_u = plane.degree_v = 1;
    plane.size_u = plane.size_v = 2;
    plane.knots_u = plane.knots_v = {0, 0, 1, 1};
    const double x1 = x0 + size;
    plane.points = {{x0, x0, z}, {x0, x1, z}, {x1, x0, z}, {x1, x1, z}};
    m.surfaces.push_back(plane);
    BRep& b = m.brep;
    const int v0 = static_cast<int>(b.vertices.size());
    const Vec3 corners[4] = {{x0, x0, z}, {x1, x0, z}, {x1, x1, z}, {x0, x1, z}};
    const Vec3 uvs[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    for (const Vec3& c : corners) b.vertices.push_back({c, 1e-9});
    BRepLoop outer;
    for (int i = 0; i < 4; ++i) {
        const int e = add_edge(b, line(corners[i], corners[(i + 1) % 4]), v0 + i, v0 + (i + 1) % 4);
        outer.coedges.push_back(use(b, e, false, line(uvs[i], uvs[(i + 1) % 4])));
    }
    b.faces.push_back({static_cast<int>(m.surfaces.size()) - 1,
                       false,
                       {outer},
                       "square " + std::to_string(b.faces.size())});
}

} // namespace

TEST_CASE("brep deviation: a point whose nearest samples all lie on another face",
          "[brep_deviation]") {
    // A small square hovering h above a large one, its 16 x 16 samples
    // denser than the large one's 0.5 apart: a point on the large square
    // under the small one has only the small square's samples and edges
    // nearest, which place it h away; the wide search finds the large square.
    Model m;
    m.source = "hover";
    constexpr double kLarge = 10, kSmall = 0.5, kLift = 0.05;
    add_square(m, 0, kLarge, 0);
    add_square(m, (kLarge - kSmall) / 2, kSmall, kLift);
    BRepDeviationOptions o;
    o.relative_spacing = 0.5 / brep_diagonal(m);
    TriangleMesh mesh;
    const double c = kLarge / 2;
    mesh.positions = {{c - 0.01, c - 0.01, 0}, {c + 0.01, c - 0.01, 0}, {c, c + 0.01, 0}};
    mesh.triangles = {{0, 1, 2}};
    o.wide_search = false;
    const Deviation nearest_only = measure_brep_deviation(m, mesh, o);
    INFO("nearest samples only: mesh->face " << nearest_only.mesh_to_surface.max);
    CHECK(nearest_only.mesh_to_surface.max == Approx(kLift).margin(1e-9));
    o.wide_search = true;
    const Deviation wide = measure_brep_deviation(m, mesh, o);
    INFO("wide search: mesh->face " << wide.mesh_to_surface.max);
    CHECK(wide.mesh_to_surface.max <= 1e-12);
}
