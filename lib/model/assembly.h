// SPDX-License-Identifier: MIT
// What a CAD file says about itself beyond its geometry: the assembly tree
// (products placed by instances, a part used N times being one part placed
// N times), the names of parts and instances, the colours of parts, solids
// and faces (STEP's styled items, IGES's colour entities) and the layers
// they are on (STEP's PRESENTATION_LAYER_ASSIGNMENT, IGES's levels), as
// OpenCASCADE's XCAF reads them. Flat arrays of indices, like the B-rep.
//
// A model with an assembly holds each part's geometry once, in the part's
// own coordinates: its faces, shells and solids are consecutive ranges of
// Model::brep, part after part. flatten_assembly places every instance.
#pragma once

#include <seamless/model/brep_placement.h>

#include <map>
#include <string>
#include <vector>

namespace seamless {

struct Model;

// A colour, components in [0, 1]; a = 1 is opaque (STEP's transparency is 1 - a).
struct Rgba {
    double r = 0, g = 0, b = 0, a = 1;
    bool operator==(const Rgba&) const = default;
};

// A product with geometry of its own: the next face_count faces, shell_count
// shells and solid_count solids of the B-rep after the parts before it.
struct AssemblyPart {
    std::string name;
    int face_count = 0, shell_count = 0, solid_count = 0;
    int colour = -1; // index into Assembly::colours; -1: none
};

// A node of the tree: an instance of a part (part >= 0) or an assembly whose
// children are the nodes naming it as their parent.
struct AssemblyNode {
    std::string name;
    int parent = -1;     // a node before this one; -1: a root
    AffineMap placement; // this node's coordinates in its parent's
    int part = -1;       // index into Assembly::parts; -1: an assembly
};

// A layer: a name and what the file assigns to it. A part stands for all
// its instances, a solid for its faces; `faces` holds only faces outside the
// listed solids. Items a mesh does not keep (curves, points) are not listed:
// a layer may list nothing.
struct AssemblyLayer {
    std::string name;
    bool visible = true;     // false: the file hides it (STEP's INVISIBILITY)
    std::vector<int> parts;  // indices into Assembly::parts
    std::vector<int> solids; // B-rep solids
    std::vector<int> faces;  // B-rep faces
    bool operator==(const AssemblyLayer&) const = default;
};

struct Assembly {
    std::vector<AssemblyPart> parts; // empty: the B-rep is the model as placed
    std::vector<AssemblyNode> nodes; // parents before their children
    std::vector<Rgba> colours;
    // Empty, or one colour index (-1: none) per B-rep solid and face: a
    // face's colour is its own, else its solid's, else its part's.
    std::vector<int> solid_colours, face_colours;
    std::vector<AssemblyLayer> layers; // in the file's order

    bool empty() const {
        return parts.empty() && nodes.empty() && colours.empty() && solid_colours.empty() &&
               face_colours.empty() && layers.empty();
    }
    bool has_tree() const { return !parts.empty(); }
};

// Where part k's items start in the B-rep (prefix sums of the counts).
struct PartRange {
    int first_face = 0, face_count = 0;
    int first_shell = 0, shell_count = 0;
    int first_solid = 0, solid_count = 0;
};
std::vector<PartRange> part_ranges(const Assembly& a);

// Each B-rep face's part (index into a.parts), -1 for none; one per face of
// a model whose B-rep has `faces` faces.
std::vector<int> face_parts(const Assembly& a, size_t faces);

// The number of nodes that place a part.
int instance_count(const Assembly& a);

// The placement of every node in world coordinates (its ancestors' composed).
std::vector<AffineMap> world_placements(const Assembly& a);

// a then b: p -> b(a(p)).
AffineMap then(const AffineMap& a, const AffineMap& b);

// Each B-rep face's colour index (face over solid over part), -1 for none;
// one per face of m.brep.
std::vector<int> face_colours(const Model& m);

// Checks m.assembly against m's B-rep: counts adding up to the B-rep's,
// each part's shells using its own faces and its solids its own shells,
// parents before children, indices in range, placements finite, within
// kMaxCoordinate and invertible, colours in [0, 1]. Messages name the
// field: "assembly.nodes[3].placement[5]". Layers' indices are checked
// against the parts and the B-rep's solids and faces.
void validate_assembly(const Model& m, const std::string& file);

// The B-rep faces `layer` of m covers, ascending: its solids' faces and its
// faces, and with `with_parts` its parts' faces too.
std::vector<int> layer_faces(const Model& m, const AssemblyLayer& layer, bool with_parts);

// The layers of a flattened model (flatten_assembly): m's layers with each
// part, solid and face listed once per copy, copies in the order of the
// nodes placing them; `first_face[k]`, `first_solid[k]`: where node k's copy
// starts in the flattened B-rep (-1 for a node placing no part).
std::vector<AssemblyLayer> placed_layers(const Model& m, const std::vector<int>& first_face,
                                         const std::vector<int>& first_solid);

// "#55", then "#55.2", "#55.3" ...: the names the file reader gives the
// copies of an instanced face (read_step_iges.cpp, face_names), and
// flatten_assembly the copies of faces and solids, in order of use.
class CopyNames {
  public:
    std::string operator()(const std::string& name) {
        const int n = uses_[name]++;
        return n == 0 ? name : name + "." + std::to_string(n + 1);
    }

  private:
    std::map<std::string, int> uses_;
};

// The model with every instance placed: each part's faces (and their
// surfaces, edges, curves, vertices) copied once per instance, mapped to
// world coordinates, names made unique as the file reader makes them ("#55",
// "#55.2", ...), the face colours resolved per copy, the layers' parts,
// solids and faces listed per copy (a part as its copies' solids and the
// faces outside them). A model without a tree is returned as it is.
Model flatten_assembly(const Model& m);

} // namespace seamless
