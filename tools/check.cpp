// SPDX-License-Identifier: MIT
// seamless check MESH: watertightness verification (issue 4, docs/check.md).
#include "commands.h"

#include <seamless/mesh/check.h>
#include <seamless/mesh/mesh_io.h>

#include <nlohmann/json.hpp>

#include <iostream>
#include <memory>
#include <sstream>

namespace seamless::cli {
namespace {

std::string point(Vec3 p) {
    std::ostringstream os;
    os.precision(10);
    os << "(" << p.x << ", " << p.y << ", " << p.z << ")";
    return os.str();
}

// Prints up to `max` entries of a defect list with a heading and its count.
template <class T, class F>
void print_list(std::ostream& os, const char* heading, const std::vector<T>& v, F&& line,
                size_t max = 10) {
    os << heading << ": " << v.size() << "\n";
    for (size_t i = 0; i < v.size() && i < max; ++i) os << "  " << line(v[i]) << "\n";
    if (v.size() > max) os << "  ... " << (v.size() - max) << " more (--json lists them)\n";
}

void print_report(std::ostream& os, const CheckReport& r) {
    os.precision(10);
    if (r.welded)
        os << "welded " << r.welded_vertices << " of " << r.input_vertices
           << " vertices with bit-identical positions\n";
    else
        os << "no welding (--no-weld): " << r.input_vertices << " vertices as indexed\n";
    os << "vertices " << r.vertices << ", triangles " << r.triangles << ", edges " << r.edges
       << ", components (shells) " << r.components.size();
    if (r.unreferenced_vertices) os << ", unreferenced vertices " << r.unreferenced_vertices;
    os << "\n";
    os << "d_max " << r.d_max << ", gap tolerance " << r.gap << "\n";
    os << "border edges " << r.border_edges << " in " << r.border_loops.size() << " loop"
       << (r.border_loops.size() == 1 ? "" : "s") << ": " << (r.closed ? "closed" : "open") << "\n";
    for (size_t i = 0; i < r.border_loops.size() && i < 10; ++i) {
        const auto& l = r.border_loops[i];
        os << "  loop of " << l.edges << " edges, length " << l.length << ", at " << point(l.start)
           << (l.closed ? "" : " (not closed)") << "\n";
    }
    if (r.border_loops.size() > 10) os << "  ... " << r.border_loops.size() - 10 << " more\n";
    print_list(os, "non-manifold edges", r.non_manifold_edges, [](const EdgeDefect& e) {
        return point(e.p0) + " - " + point(e.p1) + ", " + std::to_string(e.triangles) +
               " triangles";
    });
    print_list(os, "non-manifold vertices (a shell pinched)", r.non_manifold_vertices,
               [](const VertexDefect& v) { return point(v.position); });
    print_list(os, "shell contacts (shells touching at a vertex, not a defect)", r.shell_contacts,
               [](const VertexDefect& v) { return point(v.position); });
    print_list(os, "T-junctions", r.t_junctions, [](const TJunction& t) {
        std::ostringstream s;
        s << "vertex " << t.vertex << " at " << point(t.position) << " on an edge of triangle "
          << t.triangle << ", distance " << t.distance;
        return s.str();
    });
    print_list(os, "cracks (border edges)", r.cracks, [](const Crack& c) {
        std::ostringstream s;
        s << "triangle " << c.triangle << " edge at " << point(c.location)
          << " runs along triangle " << c.other_triangle << ", gap " << c.gap;
        return s.str();
    });
    if (!r.cracks.empty()) os << "widest crack gap: " << r.widest_crack << "\n";
    auto tri = [](const TriangleDefect& d) {
        return "triangle " + std::to_string(d.triangle) + " at " + point(d.location);
    };
    auto pair = [](const TrianglePair& p) {
        return "triangles " + std::to_string(p.t0) + " and " + std::to_string(p.t1) + " at " +
               point(p.location);
    };
    print_list(os, "degenerate triangles", r.degenerate_triangles, tri);
    print_list(os, "duplicated triangles", r.duplicated_triangles, pair);
    print_list(os, "inconsistently oriented neighbours", r.inconsistent_orientation, pair);
    print_list(os, "self-intersections within a shell", r.self_intersections, pair);
    print_list(os, "overlaps between shells (not a defect)", r.overlaps, pair, 5);
    for (size_t c = 0; c < r.components.size(); ++c) {
        const auto& C = r.components[c];
        if (c >= 20) {
            os << "... " << r.components.size() - 20 << " more shells\n";
            break;
        }
        os << "shell " << c << ": " << C.triangles << " triangles, "
           << (C.closed ? "closed" : "open (" + std::to_string(C.border_edges) + " border edges)");
        if (C.euler) os << ", Euler characteristic " << *C.euler;
        if (C.genus) os << ", genus " << *C.genus;
        if (C.volume) os << ", volume " << *C.volume;
        if (C.outward) os << (*C.outward ? ", outward" : ", inward");
        os << "\n";
    }
    os << "defects: " << defect_count(r) << "\n";
}

} // namespace

void add_check(CLI::App& app, Action& action) {
    auto* cmd = app.add_subcommand(
        "check", "Verify a triangle mesh is watertight: borders, cracks, T-junctions, "
                 "non-manifold elements, orientation, self-intersections (exit 1 on defects)");
    auto mesh_path = std::make_shared<std::string>();
    auto as_json = std::make_shared<bool>(false);
    auto opts = std::make_shared<CheckOptions>();
    auto no_weld = std::make_shared<bool>(false);
    cmd->add_option("MESH", *mesh_path, "mesh file (.off .obj .ply .stl .gltf .glb)")->required();
    cmd->add_flag("--json", *as_json, "print the whole report as JSON");
    cmd->add_flag("--closed", opts->require_closed, "also fail unless every component is closed");
    cmd->add_option("--gap", opts->gap,
                    "tolerance for cracks and T-junctions, model units (default 1e-6 * d_max)")
        ->check(CLI::PositiveNumber);
    cmd->add_flag("--no-weld", *no_weld,
                  "do not weld bit-identical vertices; judge the file's own indices");
    cmd->callback([&action, mesh_path, as_json, opts, no_weld] {
        action = [mesh_path, as_json, opts, no_weld] {
            opts->weld = !*no_weld;
            const TriangleMesh mesh = read_mesh(*mesh_path);
            const CheckReport report = check_mesh(mesh, *opts);
            const bool passed = check_passed(report, *opts);
            if (*as_json) {
                auto j = nlohmann::json::parse(to_json(report));
                j["file"] = *mesh_path;
                j["passed"] = passed;
                std::cout << j.dump(2) << "\n";
            } else {
                std::cout << *mesh_path << "\n";
                print_report(std::cout, report);
                std::cout << (passed ? "PASS" : "FAIL");
                if (!passed && defect_count(report) == 0)
                    std::cout << " (--closed: some component is open)";
                std::cout << "\n";
            }
            return passed ? 0 : 1;
        };
    });
}

} // namespace seamless::cli
