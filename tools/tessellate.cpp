// SPDX-License-Identifier: MIT
// seamless tessellate MODEL -o OUT: crack-free adaptive triangulation (paper
// section 6) with the tolerances of section 8, written in OUT's format.
#include "commands.h"
#include "model_options.h"
#include "number_options.h"
#include "progress.h"
#include <seamless/base/error.h>

#include <seamless/base/files/atomic_file.h>
#include <seamless/base/files/output_files.h>
#include <seamless/base/parallel/huge_pages.h>
#include <seamless/base/parallel/workers_warm_up.h>
#include <seamless/mesh/io/mesh_formats.h>
#include <seamless/mesh/io/mesh_io.h>
#include <seamless/mesh/io/placed_mesh.h>
#include <seamless/mesh/placed_stats_json.h>
#include <seamless/model/length_unit.h>
#include <seamless/model/model.h>
#include <seamless/tessellate/tessellation.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

namespace seamless::cli {
namespace {

struct TessellateArgs {
    std::string model, out, stats;
    double eps1 = -1, eps2 = -1, seam_tolerance = -1, tolerance = 0, angle = 0;
    int max_depth = TessellationOptions{}.max_depth;
    long long max_triangles = TessellationOptions{}.max_triangles;
    int threads = TessellationOptions{}.threads;
    bool allow_holes = TessellationOptions{}.allow_holes;
    bool flatten = false, merge = false;
    std::string units = "metres";
    ModelLoadOptions load;
};

void add_tessellate_options(CLI::App* cmd, TessellateArgs& args) {
    cmd->add_option("MODEL", args.model,
                    "model file (.json, Newell .bpt, STEP .step/.stp, IGES .iges/.igs)")
        ->required();
    cmd->add_option("-o,--output", args.out,
                    "mesh file; format by extension (" + mesh_extensions() +
                        "); OBJ and PLY of a STEP/IGES model carry each triangle's B-rep face "
                        "and part, glTF its face (face ids)")
        ->required();
    cmd->add_option("--eps1", args.eps1,
                    "planarity tolerance in model units (default 0.001 * d_max)")
        ->check(finite_number(Bound::positive));
    cmd->add_option("--eps2", args.eps2,
                    "boundary straightness tolerance in model units (default 0.02 * d_max)")
        ->check(finite_number(Bound::positive));
    cmd->add_option("--seam-tolerance", args.seam_tolerance,
                    "surfaces whose boundaries are closer than this (model units) share their "
                    "vertices there (default 1e-9 * d_max)")
        ->check(finite_number(Bound::non_negative));
    cmd->add_option("--tolerance", args.tolerance,
                    "requested deviation in model units: subdivide until the certified two-way "
                    "distance between surfaces and mesh is at most this (planarity test off "
                    "unless --eps1/--eps2 are given); B-rep models (trimmed faces) default to "
                    "0.001 of their bounding box diagonal")
        ->check(finite_number(Bound::positive));
    cmd->add_option("--angle", args.angle,
                    "also bound the angle between the normals of neighbouring triangles, degrees "
                    "(B-rep models default to 28.6, 0.5 radians)")
        ->check(CLI::Range(0.0, 180.0));
    cmd->add_option("--max-depth", args.max_depth, "most halvings per Bezier patch")
        ->check(CLI::Range(0, 60));
    cmd->add_option("--max-triangles", args.max_triangles,
                    "refuse (exit 2, no output) a tolerance that needs more triangles than this "
                    "(peak memory about 0.7 KB per triangle)")
        ->capture_default_str()
        ->check(CLI::Range(1LL, 2'000'000'000LL));
    cmd->add_option("--threads", args.threads,
                    "worker threads (0: all cores; 1: sequential); the mesh is the same for any")
        ->check(CLI::Range(0, 1024));
    cmd->add_option("--stats", args.stats, "also write the statistics as JSON to this file");
    cmd->add_flag("--allow-holes", args.allow_holes,
                  "B-rep models: write the mesh without a face that cannot be triangulated, "
                  "with a warning naming it (default: refuse the model, naming the face)");
    auto* flatten =
        cmd->add_flag("--flatten", args.flatten,
                      "glTF of a STEP/IGES assembly: one node per face with every instance placed, "
                      "as the other formats (default: the assembly's tree, each part meshed once "
                      "and shared by its instances, with the file's names and colours)");
    cmd->add_flag("--merge", args.merge,
                  "glTF of a STEP/IGES model: one mesh and node for every instance placed, one "
                  "primitive per colour")
        ->excludes(flatten);
    cmd->add_option("--units", args.units,
                    "glTF: 'metres' scales a STEP/IGES file's coordinates from its length unit "
                    "(millimetres, inches, ...) to glTF's metres; 'keep' leaves them in the "
                    "file's unit (other models and formats are never scaled)")
        ->capture_default_str()
        ->check(CLI::IsMember({"metres", "keep"}));
    add_model_options(cmd, args.load);
}

TessellationOptions tessellation_options(const TessellateArgs& args) {
    TessellationOptions opt;
    opt.eps1 = args.eps1;
    opt.eps2 = args.eps2;
    opt.max_depth = args.max_depth;
    opt.max_triangles = args.max_triangles;
    opt.seam_tolerance = args.seam_tolerance;
    opt.tolerance = args.tolerance;
    opt.threads = args.threads;
    opt.allow_holes = args.allow_holes;
    opt.angle = args.angle * 3.14159265358979323846 / 180;
    opt.patch_trees = false; // the renderer's, not written
    return opt;
}

// B-rep models' default deviation, 0.001 of the diagonal of the box of the
// B-rep's vertices and curves (brep_tessellation.cpp), for the model placed.
double placed_default_tolerance(const Model& m) {
    const Model flat = flatten_assembly(m);
    Box3 box;
    for (const BRepVertex& v : flat.brep.vertices) box.extend(v.point);
    for (const BSplineCurve& c : flat.brep.curves)
        for (const Vec3& p : c.points) box.extend(p);
    if (box.empty() || !(norm(box.extent()) > 0)) box.extend(control_box(flat));
    return 1e-3 * norm(box.extent());
}

void print_tessellation_summary(const TessellationStats& s) {
    if (s.brep.faces > 0) {
        const BRepStats& b = s.brep;
        std::cout << b.faces << " B-rep faces, " << b.edges << " edges, " << s.triangles
                  << " triangles, " << s.vertices << " vertices, sampled deviation "
                  << b.max_deviation << ", certified bound ";
        if (std::isnan(s.max_error_bound))
            std::cout << "with --stats";
        else
            std::cout << s.max_error_bound;
        std::cout << " (tolerance " << s.tolerance << ")";
        if (s.surfaces > b.faces) std::cout << ", " << s.subpatches << " free-surface subpatches";
        std::cout << ", " << s.seconds << " s\n";
        return;
    }
    std::cout << s.surfaces << " surfaces, " << s.patches << " patches, " << s.subpatches
              << " subpatches, " << s.triangles << " triangles, " << s.vertices
              << " vertices, certified bound " << s.max_error_bound;
    if (s.tolerance > 0)
        std::cout << " (tolerance " << s.tolerance << ", " << s.above_tolerance
                  << " subpatches above)";
    std::cout << ", " << s.seconds << " s\n";
}

int run_tessellate(const TessellateArgs& args) {
    // Refuse an unknown output format before doing the work.
    (void)mesh_format(std::filesystem::path(args.out));
    // Every output checked (writable, not an input) before the work.
    std::vector<std::filesystem::path> outs{args.out};
    if (!args.stats.empty()) outs.push_back(args.stats);
    OutputFiles files(outs, {args.model});
    keep_freed_memory(); // the passes reuse each other's pages (huge_pages.h)
    const MeshFormat format = mesh_format(std::filesystem::path(args.out));
    ModelLoadOptions load = args.load;
    // Each part is meshed once; placed_mesh places its instances.
    load.keep_assembly = true;
    const Model m = [&] {
        const WorkersWarmUp warm_up(args.threads); // while the model is read
        return load_model(args.model, load);
    }();
    print_warnings(m);
    TessellationOptions opt = tessellation_options(args);
    const bool tree = m.assembly.has_tree();
    // The parts lie in their own coordinates: the default deviation is that
    // of the model as placed.
    if (tree && opt.tolerance == 0) opt.tolerance = placed_default_tolerance(m);
    // The B-rep's certified bound (brep_certification.h) costs up to about
    // the tessellation's own time: only --stats reports it.
    if (!m.brep.empty() && args.stats.empty()) opt.certify = false;
    ProgressBar bar("tessellate");
    opt.progress = [&bar](double f) { bar.update(f); };
    const Tessellation t = [&] {
        try {
            return tessellate(m, opt);
        } catch (const TriangleBudgetError& e) { // name this command's flag
            throw InputError(e.file(), e.field(),
                             TriangleBudgetError::message_for(e.limit(), "--max-triangles"));
        }
    }();
    bar.finish();
    for (const std::string& w : t.stats.brep.warnings) std::cerr << "warning: " << w << "\n";
    GltfWriteOptions gltf;
    gltf.merge = args.merge;
    const bool is_gltf = format == MeshFormat::gltf || format == MeshFormat::glb;
    if (is_gltf && args.units == "metres")
        if (const double unit = file_length_unit(args.model); unit > 0) gltf.scale = unit;
    if (is_gltf && !args.flatten && !m.brep.empty() && (args.merge || !m.assembly.empty()))
        write_mesh_assembly(files.staging(0), t.mesh, m, gltf);
    else
        write_mesh(files.staging(0), placed_mesh(t.mesh, m), gltf);
    print_tessellation_summary(t.stats);
    if (gltf.scale != 1)
        std::cout << "coordinates scaled to metres: 1 file unit = " << gltf.scale << " m\n";
    if (const PlacedCounts placed = tree ? placed_counts(t.mesh, m) : PlacedCounts{}; tree)
        std::cout << "assembly placed (instances: " << instance_count(m.assembly)
                  << ", parts: " << m.assembly.parts.size() << "): " << placed.triangles
                  << " triangles, " << placed.vertices << " vertices\n";
    if (!args.stats.empty())
        write_text_atomically(
            files.staging(1),
            placed_stats_json(t.stats, {args.model, args.out, args.angle}, t.mesh, m) + "\n");
    files.commit(); // both outputs, or neither
    return 0;
}

} // namespace

void add_tessellate(CLI::App& app, Action& action) {
    auto* cmd = app.add_subcommand(
        "tessellate", "Triangulate a model into a crack-free mesh (planar subpatches, "
                      "straight-midpoint edge vertices, fans of four or more triangles; with "
                      "--tolerance, two where certified; trimmed B-rep faces: shared edge "
                      "polylines and constrained triangulations)");
    auto args = std::make_shared<TessellateArgs>();
    add_tessellate_options(cmd, *args);
    cmd->callback([&action, args] { action = [args] { return run_tessellate(*args); }; });
}

} // namespace seamless::cli
