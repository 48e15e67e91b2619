// SPDX-License-Identifier: MIT
#include <seamless/tessellate/trimmed/face_trees.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

using namespace seamless;

namespace {

// `faces` faces of `per_face` random small triangles each in the unit cube.
TriangleMesh random_triangles(int faces, int per_face, std::vector<int>& face_first) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0, 1), d(-0.02, 0.02);
    TriangleMesh m;
    face_first = {0};
    for (int f = 0; f < faces; ++f) {
        for (int k = 0; k < per_face; ++k) {
            const Vec3 c{u(rng), u(rng), u(rng)};
            const int v = m.vertex_count();
            for (int i = 0; i < 3; ++i) m.positions.push_back(c + Vec3{d(rng), d(rng), d(rng)});
            m.triangles.push_back({v, v + 1, v + 2});
        }
        face_first.push_back(m.triangle_count());
    }
    return m;
}

bool contains(const Box3& outer, const Box3& inner) {
    for (int i = 0; i < 3; ++i)
        if (inner.lo[i] < outer.lo[i] || inner.hi[i] > outer.hi[i]) return false;
    return true;
}

} // namespace

TEST_CASE("face trees hold every triangle of each face once, below hulls that hold it") {
    std::vector<int> face_first;
    const TriangleMesh m = random_triangles(5, 37, face_first);
    face_first.insert(face_first.begin() + 3, face_first[2]); // a face without triangles
    const PatchTrees trees = face_trees(m, face_first);
    REQUIRE(trees.roots.size() == face_first.size() - 1);
    std::vector<int> seen(m.triangle_count(), 0);
    for (size_t f = 0; f < trees.roots.size(); ++f) {
        std::vector<int> stack{trees.roots[f]};
        while (!stack.empty()) {
            const PatchNode& n = trees.nodes[stack.back()];
            const int id = stack.back();
            stack.pop_back();
            if (n.triangle >= 0) {
                ++seen[n.triangle];
                CHECK(n.triangle >= face_first[f]);
                CHECK(n.triangle < face_first[f + 1]);
                Box3 b;
                for (int v : m.triangles[n.triangle]) b.extend(m.positions[v]);
                CHECK(contains(n.triangle_hull, b));
            }
            for (int c : n.child)
                if (c >= 0) {
                    CHECK(c > id);
                    CHECK(contains(n.triangle_hull, trees.nodes[c].triangle_hull));
                    stack.push_back(c);
                }
        }
    }
    for (int s : seen) CHECK(s == 1);
    CHECK(trees.depth <= 7); // median splits of 37 triangles: ceil(log2 37) = 6 levels
}

TEST_CASE("a box query over face trees finds exactly the triangles a brute-force scan finds") {
    std::vector<int> face_first;
    const TriangleMesh m = random_triangles(3, 200, face_first);
    const PatchTrees trees = face_trees(m, face_first);
    const Box3 query{{0.2, 0.3, 0.1}, {0.5, 0.6, 0.45}};
    auto overlaps = [&](const Box3& b) {
        for (int i = 0; i < 3; ++i)
            if (b.hi[i] < query.lo[i] || b.lo[i] > query.hi[i]) return false;
        return true;
    };
    std::vector<int> found, expected;
    visit_candidate_triangles(trees, overlaps, [&](int t) { found.push_back(t); });
    for (int t = 0; t < m.triangle_count(); ++t) {
        Box3 b;
        for (int v : m.triangles[t]) b.extend(m.positions[v]);
        if (overlaps(b)) expected.push_back(t);
    }
    std::sort(found.begin(), found.end());
    CHECK(!expected.empty());
    CHECK(found == expected);
}
