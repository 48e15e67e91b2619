// SPDX-License-Identifier: MIT
// What a tessellation hands on: the crack-free mesh, its binary patch trees
// (Proposition 11, remark 2), the planar subpatches with their certified
// bounds, and what it counted and measured (--stats, docs/formats.md).
#pragma once

#include <seamless/base/error.h>
#include <seamless/base/triangle_mesh.h>
#include <seamless/tessellate/subdivision/patch_tree.h>
#include <seamless/tessellate/subdivision/subdivision.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace seamless {

// Wall-clock seconds of the phases of tessellate(), summed over the passes
// (docs/formats.md, `phase_seconds`). In parallel: subdivision, rings,
// bounds, normals, scaling (the power-of-two scale in and out), and but for
// prefix sums fans (triangles, patch-tree leaves, hulls), orientation and,
// without straight segments, numbering (vertices in subpatch order); on one
// thread: boundaries (shared edges, edge registry and graph).
struct PhaseSeconds {
    double subdivision = 0, boundaries = 0, rings = 0, numbering = 0, bounds = 0, normals = 0,
           fans = 0, orientation = 0, scaling = 0;
};

// What the trimmed-face pipeline (tessellate/trimmed/) counted and measured.
struct BRepStats {
    int faces = 0, edges = 0; // of the B-rep, tessellated
    int edge_points = 0;      // mesh vertices inside edges (shared by their faces)
    int interior_points = 0;  // mesh vertices inside faces
    int resplit_rounds = 0;   // rounds that re-split the edges of faces whose CDT failed
    int resplit_edges = 0;    // edges re-split in them
    // Work counters: faces triangulated (a face redone after a re-split
    // counts again) and triangles judged against D and the angle.
    long long face_runs = 0, judged_triangles = 0;
    int faces_left_out = 0;  // by TessellationOptions::allow_holes
    int above_tolerance = 0; // triangles the refinement limits stopped above D or the angle
    double angle = 0;        // radians, used (0.5 by default)
    // Largest sampled distance between the faces and the mesh, model units:
    // edge chords against the 3D curves, and triangles against the surface at
    // barycentric samples mapped through (u,v). Measured, not certified.
    double max_deviation = 0;
    double max_edge_tolerance = 0; // largest edge tolerance, as the file claims it
    // Largest measured distance between a boundary point (on its edge's 3D
    // curve) and its face's surface at the pcurve's point: the B-rep's own
    // gap, which no mesh of both faces closes to below it.
    double max_edge_offset = 0;
    int edges_above_tolerance = 0; // edges whose tolerance exceeds D
    bool certified = false;        // max_deviation is a sampled measure, not a bound
    // Certified bounds (TessellationOptions::certify; brep_certification.h):
    // between each triangle and its face (both ways) and between each edge
    // chord and its curve; TessellationStats::max_error_bound is the larger.
    // The slivers between pcurves and their (u,v) chords are not covered.
    double bound_triangles = 0, bound_chords = 0;
    double bound_seconds = 0; // of TessellationStats::seconds, spent on the bounds
    // Of the meshing (seconds less bound_seconds): discretising the edges,
    // triangulating the faces (re-split rounds included) and joining them.
    double edge_seconds = 0, face_seconds = 0, mesh_seconds = 0;
    std::vector<std::string> warnings; // one line each: faces left out, tolerances above D
};

struct TessellationStats {
    int surfaces = 0, patches = 0, subpatches = 0, triangles = 0, vertices = 0;
    int shared_edges = 0, collapsed_edges = 0;
    int seams = 0, seam_vertices = 0;     // boundaries matched geometrically (edge_graph.h)
    int flipped_surfaces = 0;             // turned by orient_surfaces
    int nonplanar_subpatches = 0;         // stopped by max_depth
    int two_triangle_subpatches = 0;      // Subpatch::diagonal: two triangles, not a fan
    int max_depth = 0;                    // deepest subpatch
    double d_max = 0, eps1 = 0, eps2 = 0; // eps: 0 when the planarity test was off
    double seam_tolerance = 0;
    double tolerance = 0; // requested (0: none), model units
    // Largest Subpatch::error_bound: the certified two-way distance between the
    // surfaces and the mesh, model units (NaN when TessellationOptions::certify
    // left it out).
    double max_error_bound = 0;
    // Subpatches whose final bound exceeds the tolerance (neighbours moved a
    // corner onto their straight edge after the subpatch passed), or that
    // max_depth stopped.
    int above_tolerance = 0;
    int passes = 1; // tessellation passes (a tolerance may need more than one)
    double seconds = 0;
    PhaseSeconds phases;
    BRepStats brep; // B-rep models only (Model::brep non-empty)
};

// What tessellate() throws past TessellationOptions::max_triangles: an
// InputError naming the model and the tolerance that asked for it, with the
// limit kept so a front end can name its own way to raise it.
class TriangleBudgetError : public InputError {
  public:
    TriangleBudgetError(std::string file, std::string field, std::int64_t limit)
        : InputError(std::move(file), std::move(field), message_for(limit, "max_triangles")),
          limit_(limit) {}
    std::int64_t limit() const { return limit_; }
    // The message, with the limit called by `name` (a front end's own flag).
    static std::string message_for(std::int64_t limit, const std::string& name) {
        return "needs more than " + std::to_string(limit) + " triangles, the " + name +
               " limit; a larger tolerance needs fewer";
    }

  private:
    std::int64_t limit_;
};

struct Tessellation {
    TriangleMesh mesh;
    PatchTrees trees;
    // Planar subpatches in tree order, with their triangle ranges and error bounds.
    std::vector<Subpatch> subpatches;
    TessellationStats stats;
};

} // namespace seamless
