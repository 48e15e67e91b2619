// SPDX-License-Identifier: MIT
// A model: the B-spline surfaces of one file and, for CAD files with trimmed
// faces, their boundary representation (brep.h). Readers for the JSON model
// format (version 1: surfaces; version 2: surfaces and a B-rep), the Newell Bezier patch format
// (.bpt) and, through OpenCASCADE, STEP and IGES (step_iges.h); docs/formats.md documents them and
// their error messages.
#pragma once

#include <seamless/base/vec.h>
#include <seamless/model/assembly.h>
#include <seamless/model/brep.h>
#include <seamless/spline/bezier_patch.h>
#include <seamless/spline/bspline_surface.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace seamless {

// Where a surface read from a CAD file came from (step_iges.h).
struct SurfaceOrigin {
    std::string entity;             // the file's entity, e.g. "#55" (STEP) or "DE9" (IGES)
    std::string kind;               // "B-spline", "Bezier", "plane", "cylinder", "torus", ...
    bool exact = true;              // converted to its exact NURBS form
    double approximation_error = 0; // else: the approximation's largest distance from the
                                    // file's surface, as OpenCASCADE measures it, model units
};

struct Model {
    std::string source; // file the model came from, for messages
    std::vector<BSplineSurface> surfaces;
    std::vector<SurfaceOrigin> origins; // one per surface for STEP/IGES, empty otherwise
    std::vector<std::string> warnings;  // what the reader left out or approximated, one line each
    // Empty: the surfaces are the model, each its whole (u,v) rectangle. Else
    // the model is the B-rep's faces, each a trimmed part of its surface.
    BRep brep;
    // Empty: no structure. Else the file's tree, names and colours; with a
    // tree, `brep` holds each part once in its own coordinates (assembly.h).
    Assembly assembly;
};

// Limits that reject absurd sizes before anything is allocated for them.
struct ModelLimits {
    long long max_surfaces = 1'000'000;
    long long max_control_points = 50'000'000;               // per surface, nu * nv
    std::uintmax_t max_file_bytes = std::uintmax_t(1) << 30; // 1 GiB
    long long max_brep_items = 10'000'000;  // B-rep faces, edges, vertices, curves, coedges each
    long long max_curve_points = 1'000'000; // control points per curve or pcurve
};

// Largest magnitude of a control point coordinate, 2^510 (about 3.4e153).
// Coordinates up to it keep every difference of two points below 2^511, so
// squared distances (3 * 2^1022) and cross products (2^1023) of any two
// points of a model or of its mesh are finite doubles: d_max, the mesh checks
// and the deviation measures can be computed without overflow. Tessellation
// itself works at a power-of-two scale where d_max is near 1 (exact), so any
// magnitude within the limit tessellates to the same mesh, scaled. The
// renderer needs a stricter bound; scenes apply it (scene.h).
inline constexpr double kMaxCoordinate = 0x1p510;
// Weights lie in [2^-256, 2^256]: homogeneous points w * P stay below 2^766.
// Knots are bounded by kMaxCoordinate, so knot differences are finite.
inline constexpr double kMaxWeight = 0x1p256;

// What to do with a STEP/IGES face whose boundary is not its surface's
// parameter rectangle (a trimmed face).
enum class TrimmedFaces {
    brep,          // the file is read as a B-rep (Model::brep) when it has trimmed faces
    refuse,        // the file is refused with one line naming the trimmed faces
    skip,          // they are left out (a warning names them)
    whole_surface, // their whole underlying surfaces are taken (a warning names them)
};

struct ModelLoadOptions {
    ModelLimits limits;
    TrimmedFaces trimmed = TrimmedFaces::brep;
    // Surfaces without an exact NURBS form (offset surfaces, revolutions of
    // offset curves, degrees above kMaxDegree) are approximated within this
    // fraction of their bounding box diagonal; the error reached is reported.
    double approximation_tolerance = 1e-7;
    // STEP and IGES are read in a process of their own (step_iges.h), stopped
    // past these limits with one InputError naming the file: wall-clock
    // seconds (0: none), and bytes of address space (RLIMIT_AS; 0: none; not
    // applied in AddressSanitizer builds, whose shadow memory takes terabytes
    // of it). docs/formats.md, Limits.
    double reader_time_limit = 600; // far above the slowest corpus file (docs/formats.md, Limits)
    std::uint64_t reader_memory_limit = std::uint64_t(4) << 30; // 4 GiB
    // An assembly is placed into one B-rep (flatten_assembly) unless this
    // asks for it as the file has it: each part once, with its instances.
    bool keep_assembly = false;
};

// Reads a model by extension: .json, .bpt, .step/.stp, .iges/.igs (anything
// else is tried as JSON). Throws InputError naming the file and the field on
// any defect.
Model load_model(const std::filesystem::path& path, const ModelLoadOptions& options = {});
Model load_model(const std::filesystem::path& path, const ModelLimits& limits);
Model parse_model_json(const std::string& text, const std::string& file,
                       const ModelLimits& limits = {});
Model parse_bpt(const std::string& text, const std::string& file, const ModelLimits& limits = {});

// Checks degrees, sizes, knots (count, order, multiplicity <= degree+1, non-empty
// domain), finiteness, coordinate magnitude (kMaxCoordinate) and weights. `field` prefixes
// messages, e.g. "surfaces[2]".
void validate_surface(const BSplineSurface& s, const std::string& file, const std::string& field);
// The same checks for a curve (a B-rep edge's curve or a pcurve) of at most
// `max_points` control points: e.g. "brep.curves[4].knots".
void validate_curve(const BSplineCurve& c, const std::string& file, const std::string& field,
                    long long max_points);

// Checks a B-rep against the model's surfaces: indices in range, sizes
// within `limits`, curves valid (degree, knots, finiteness, weights), edge
// ranges inside their curves' domains, loops closed chains in (u,v) within
// tolerance, seams used twice by one face. `field` prefixes messages
// ("brep"), e.g. "brep.faces[3].loops[0].coedges[2]".
void validate_brep(const Model& m, const std::string& file, const ModelLimits& limits = {});

// JSON text of a model: version 1 (surfaces) without a B-rep, version 2 with
// one (17 significant digits: reads back bit-identical).
std::string to_json(const Model& m);

// Bounding box of every control point; its largest extent is the paper's d_max.
Box3 control_box(const Model& m);
double d_max(const Model& m);

// Bezier patches of every surface, in surface order (paper section 4).
std::vector<BezierPatch> bezier_patches(const Model& m);

} // namespace seamless
