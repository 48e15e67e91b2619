// SPDX-License-Identifier: MIT
// A check of a mesh with face ids names the faces its defects lie on.
#include "mesh/io/tessellated.h"

#include <seamless/mesh/check/defect_faces.h>
#include <seamless/mesh/io/placed_mesh.h>

#include <catch2/catch.hpp>

#include <algorithm>

using namespace seamless;

namespace {

TriangleMesh placed_assembly() {
    const Model m = test::small_assembly();
    return placed_mesh(test::tessellated(m), m);
}

bool names_face_of(const std::vector<DefectFace>& faces, const TriangleMesh& m, int t) {
    return std::any_of(faces.begin(), faces.end(), [&](const DefectFace& f) {
        return f.face == m.triangle_face[t] && f.part == m.triangle_part[t] && f.defects > 0;
    });
}

} // namespace

TEST_CASE("A turned triangle and a hole are named by their faces", "[mesh][check][face_ids]") {
    TriangleMesh m = placed_assembly();
    const CheckReport before = check_mesh(m);
    // The last tube's copy: turn one of its triangles, drop another.
    const int turned = m.triangle_count() - 1, dropped = m.triangle_count() - 2;
    std::swap(m.triangles[turned][1], m.triangles[turned][2]);
    const int face = m.triangle_face[dropped];
    for (auto* v : {&m.triangle_face, &m.triangle_part}) v->erase(v->begin() + dropped);
    m.triangles.erase(m.triangles.begin() + dropped);
    const int now_turned = turned - 1;
    const CheckReport r = check_mesh(m);
    CHECK(r.inconsistent_orientation.size() > before.inconsistent_orientation.size());
    CHECK(r.border_edges > before.border_edges);
    const std::vector<DefectFace> faces = defect_faces(m, r);
    CHECK(names_face_of(faces, m, now_turned));
    CHECK(std::any_of(faces.begin(), faces.end(),
                      [&](const DefectFace& f) { return f.face == face && f.part == 1; }));
    CHECK(triangle_place(m, now_turned) ==
          "face " + std::to_string(m.triangle_face[now_turned]) + " of part 1 (tube)");
    // Without face ids nothing is named.
    TriangleMesh bare = m;
    bare.triangle_face.clear();
    CHECK(defect_faces(bare, r).empty());
    CHECK(triangle_place(bare, 0).empty());
}
