// SPDX-License-Identifier: MIT
// The mesh of a B-rep model as placed, with face ids (TriangleMesh's
// triangle_face, triangle_part): what the formats without an assembly tree
// (OFF, OBJ, PLY, STL, glTF --flatten and --merge) are written from. A model
// that keeps its assembly is tessellated once per part; its instances are
// copies of the part's triangles, so a part used N times is meshed once and
// every copy is the same mesh placed.
#pragma once

#include <seamless/base/triangle_mesh.h>
#include <seamless/model/model.h>

#include <vector>

namespace seamless {

// The face on each surface of `model`: -1 for a surface no face or several
// faces lie on (a STEP/IGES B-rep has one surface per face).
std::vector<int> face_of_surface(const Model& model);

// Each face's solid in `brep`: the first solid whose shells hold it, -1
// for a face in no solid.
std::vector<int> face_solids(const BRep& brep);

// Each triangle's face in `model`, by its surface (face_of_surface), -1
// where that names no one face; empty when `mesh` does not give every
// triangle's surface.
std::vector<int> triangle_faces(const TriangleMesh& mesh, const Model& model);

// Per face of flatten_assembly(model), in its order (node after node, each
// part's faces in order), the face of `model` it copies; the identity for a
// model without a tree.
std::vector<int> placed_face_sources(const Model& model);

// What placed_mesh(mesh, model) would hold, counted without placing: each
// part's triangles and vertices times its instances, plus those on surfaces
// no face lies on (once). A model without a tree: the mesh's own counts.
struct PlacedCounts {
    struct Part {
        int instances = 0;
        long long triangles = 0, vertices = 0; // of one instance
    };
    long long triangles = 0, vertices = 0;
    std::vector<Part> parts; // one per model.assembly.parts; empty without a tree
};
PlacedCounts placed_counts(const TriangleMesh& mesh, const Model& model);

// `mesh` (the tessellation of `model`) placed, with face ids. A model with a
// tree: every part's triangles copied once per instance, in
// flatten_assembly's order, positions mapped to world coordinates, normals
// by the inverse transpose, a mirroring placement's triangles turned;
// triangle_face indexes the faces of flatten_assembly(model),
// triangle_surface is the same index and surface_names the copies' names
// ("#55", "#55.2"), then the surfaces no face lies on, copied once (face and
// part -1); triangle_part indexes part_names (the parts' names, a repeated
// one made unique as "name.2"); triangle_solid indexes the solids of
// flatten_assembly(model) (face_solids; -1 for a face in no solid). A B-rep
// model without a tree: the mesh with triangle_face from its surfaces, its
// solids, and one part named after the file. A model without faces: the
// mesh as it is.
TriangleMesh placed_mesh(const TriangleMesh& mesh, const Model& model);

} // namespace seamless
