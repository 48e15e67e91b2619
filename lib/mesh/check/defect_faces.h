// SPDX-License-Identifier: MIT
// Where the defects of a check lie in the model a mesh came from: the B-rep
// faces (and parts) of the triangles each defect names, for a mesh with face
// ids (TriangleMesh::triangle_face, triangle_part: an OBJ or PLY written by
// seamless from a STEP/IGES model, docs/formats.md, "Face ids").
#pragma once

#include <seamless/mesh/check/check.h>

#include <string>
#include <vector>

namespace seamless {

// A face with defects on it: a defect counts once on each face it touches.
struct DefectFace {
    int part = -1, face = -1;
    int defects = 0;
    int triangle = -1; // a triangle of a defect on it
};

// The triangles a defect of each kind names (border loops: the triangles
// along them), as lists, one per defect, in the report's order.
std::vector<std::vector<int>> defect_triangles(const CheckReport& report);

// Every face with a defect on it, ordered by part and face; empty when the
// mesh has no face ids.
std::vector<DefectFace> defect_faces(const TriangleMesh& mesh, const CheckReport& report);

// "face 12 of part 3 (nut)", "face 12" or "no face" for triangle t of a mesh
// with face ids; "" without them.
std::string triangle_place(const TriangleMesh& mesh, int t);

// The distinct places of `triangles`, joined by ", ".
std::string places(const TriangleMesh& mesh, const std::vector<int>& triangles);

} // namespace seamless
