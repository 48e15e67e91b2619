// SPDX-License-Identifier: MIT
// What a CAD file says about itself beyond its geometry: the assembly tree
// (products placed by instances, a part used N times being one part placed
// N times), the names of parts and instances, and the colours of parts,
// solids and faces (STEP's styled items, IGES's colour entities, as
// OpenCASCADE's XCAF reads them). Flat arrays of indices, like the B-rep.
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

struct Assembly {
    std::vector<AssemblyPart> parts; // empty: the B-rep is the model as placed
    std::vector<AssemblyNode> nodes; // parents before their children
    std::vector<Rgba> colours;
    // Empty, or one colour index (-1: none) per B-rep solid and face: a
    // face's colour is its own, else its solid's, else its part's.
    std::vector<int> solid_colours, face_colours;

    bool empty() const {
        return parts.empty() && nodes.empty() && colours.empty() && solid_colours.empty() &&
               face_colours.empty();
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
// field: "assembly.nodes[3].placement[5]".
void validate_assembly(const Model& m, const std::string& file);

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
// "#55.2", ...), the face colours resolved per copy. A model without a tree
// is returned as it is.
Model flatten_assembly(const Model& m);

} // namespace seamless
