// SPDX-License-Identifier: MIT
// The CGAL constrained Delaunay triangulation behind its seamless interface:
// the domain is what lies at odd nesting across the loops, loops that cross
// or pass through a point are refused, and points are inserted only inside
// the domain, clear of its boundary.
#include <seamless/tessellate/trimmed/faces/constrained_triangulation.h>

#include <catch2/catch.hpp>

#include <algorithm>

#include <cmath>

using namespace seamless;

namespace {

// Loops as closed polygons: points and their segments, keys all distinct.
struct Loops {
    std::vector<Vec3> points;
    std::vector<std::int64_t> keys;
    std::vector<std::array<int, 2>> segments;
    void add(const std::vector<Vec3>& polygon) {
        const int first = static_cast<int>(points.size());
        for (size_t i = 0; i < polygon.size(); ++i) {
            points.push_back(polygon[i]);
            keys.push_back(static_cast<std::int64_t>(keys.size()));
            segments.push_back(
                {first + static_cast<int>(i), first + static_cast<int>((i + 1) % polygon.size())});
        }
    }
};

double area(ConstrainedTriangulation& cdt, const std::vector<Vec3>& points) {
    std::vector<DomainTriangle> tris;
    cdt.triangles(tris);
    double sum = 0;
    for (const DomainTriangle& t : tris) {
        const Vec3 a = points[t.corners[0]], b = points[t.corners[1]], c = points[t.corners[2]];
        const double twice = cross(b - a, c - a).z;
        CHECK(twice > 0); // counter-clockwise
        sum += 0.5 * twice;
    }
    return sum;
}

} // namespace

TEST_CASE("constrained triangulation: a square with a square hole", "[brep]") {
    Loops l;
    l.add({{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}});
    l.add({{1, 1, 0}, {1, 2, 0}, {2, 2, 0}, {2, 1, 0}}); // clockwise: orientation is irrelevant
    ConstrainedTriangulation cdt;
    REQUIRE(cdt.build(l.points, l.keys, l.segments));
    CHECK(area(cdt, l.points) == Approx(15));
    // Inside the hole and outside the square: refused; in the domain: taken.
    CHECK(cdt.insert({1.5, 1.5, 0}, 0, 0) == ConstrainedTriangulation::kOutside);
    CHECK(cdt.insert({5, 5, 0}, 0, 0) == ConstrainedTriangulation::kOutside);
    CHECK(cdt.insert({3.2, 2.6, 0}, 0.1, 0) == 8);
    CHECK(cdt.insert({3.21, 2.6, 0}, 0.1, 7) == ConstrainedTriangulation::kCrowded);
    CHECK(cdt.insert({3.97, 2, 0}, 0.1, 3) == ConstrainedTriangulation::kOutside); // near a side
    std::vector<Vec3> points = l.points;
    points.push_back({3.2, 2.6, 0});
    CHECK(area(cdt, points) == Approx(15));
}

TEST_CASE("constrained triangulation: crossing loops and a loop through a point are refused",
          "[brep]") {
    Loops crossing;
    crossing.add({{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}});
    crossing.add({{3, 1, 0}, {5, 1, 0}, {5, 2, 0}, {3, 2, 0}});
    ConstrainedTriangulation a;
    CHECK(!a.build(crossing.points, crossing.keys, crossing.segments));

    Loops through; // the hole's corner lies on the square's side
    through.add({{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}});
    through.add({{4, 2, 0}, {3, 1, 0}, {3, 3, 0}});
    ConstrainedTriangulation b;
    CHECK(!b.build(through.points, through.keys, through.segments));

    Loops coincide; // two points with different keys at one place
    coincide.add({{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}});
    coincide.add({{4, 4, 0}, {3, 2, 0}, {2, 3, 0}});
    ConstrainedTriangulation c;
    CHECK(!c.build(coincide.points, coincide.keys, coincide.segments));
    coincide.keys[4] = coincide.keys[2]; // the same vertex: a hole touching the outer loop
    ConstrainedTriangulation d;
    CHECK(d.build(coincide.points, coincide.keys, coincide.segments));
    CHECK(area(d, coincide.points) == Approx(16 - 1.5));
}

TEST_CASE("trimmed faces: a loop collapsed onto one line is refused, not marked") {
    // A face whose (u,v) loop is flat (trj3_s1-al's crashed the marking).
    Loops l;
    l.add({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {1, 0, 0}});
    l.keys[3] = 5; // a distinct vertex on top of point 1: refused as a duplicate too
    ConstrainedTriangulation cdt;
    CHECK_FALSE(cdt.build(l.points, l.keys, l.segments));
    Loops flat;
    flat.add({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}});
    ConstrainedTriangulation line;
    CHECK_FALSE(line.build(flat.points, flat.keys, flat.segments));
}

TEST_CASE("constrained triangulation: a tag stays with a triangle until an insertion changes it",
          "[brep]") {
    Loops l;
    l.add({{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}});
    l.add({{1, 1, 0}, {1, 2, 0}, {2, 2, 0}, {2, 1, 0}});
    ConstrainedTriangulation cdt;
    REQUIRE(cdt.build(l.points, l.keys, l.segments));
    std::vector<DomainTriangle> before;
    cdt.triangles(before);
    for (size_t k = 0; k < before.size(); ++k) {
        CHECK(before[k].tag == -1);
        cdt.set_tag(static_cast<int>(k), static_cast<int>(k));
    }
    REQUIRE(cdt.insert({3.2, 2.6, 0}, 0.1, 0) == 8);
    std::vector<DomainTriangle> after;
    cdt.triangles(after);
    int kept = 0, fresh = 0;
    for (const DomainTriangle& t : after) {
        // Tagged: the very triangle tagged before (same corners in order);
        // untagged: touching the new point or a triangle the insertion flipped.
        if (t.tag >= 0) {
            REQUIRE(t.tag < static_cast<int>(before.size()));
            CHECK(before[t.tag].corners == t.corners);
            ++kept;
        } else {
            const bool listed = std::any_of(before.begin(), before.end(),
                                            [&](const auto& b) { return b.corners == t.corners; });
            CHECK((!listed || t.corners[0] == 8 || t.corners[1] == 8 || t.corners[2] == 8));
            ++fresh;
        }
    }
    CHECK(kept > 0);
    CHECK(fresh >= 3); // the new point's fan
}
