// SPDX-License-Identifier: MIT
// seamless check MESH: watertightness verification (docs/check.md).
#include "check_report.h"
#include "commands.h"
#include "number_options.h"

#include <seamless/mesh/check/check.h>
#include <seamless/mesh/check/check_json.h>
#include <seamless/mesh/check/defect_faces.h>
#include <seamless/mesh/io/mesh_formats.h>
#include <seamless/mesh/io/mesh_io.h>

#include <nlohmann/json.hpp>

#include <iostream>
#include <memory>
#include <sstream>

namespace seamless::cli {

void add_check(CLI::App& app, Action& action) {
    auto* cmd = app.add_subcommand(
        "check", "Verify a triangle mesh is watertight: borders, seam cracks, T-junctions, "
                 "non-manifold elements, orientation, self-intersections (exit 1 on defects)");
    auto mesh_path = std::make_shared<std::string>();
    auto as_json = std::make_shared<bool>(false);
    auto opts = std::make_shared<CheckOptions>();
    auto no_weld = std::make_shared<bool>(false);
    std::ostringstream gap_help;
    gap_help << "absolute tolerance for cracks and T-junctions, model units (default: "
             << opts->relative_gap * 100 << "% of the local edge length, at least "
             << opts->gap_floor << " * d_max)";
    cmd->add_option("MESH", *mesh_path, "mesh file (" + mesh_extensions() + ")")->required();
    cmd->add_flag("--json", *as_json, "print the whole report as JSON");
    cmd->add_flag("--closed", opts->require_closed, "also fail unless every component is closed");
    cmd->add_option("--gap", opts->gap, gap_help.str())->check(finite_number(Bound::positive));
    auto whole = std::make_shared<bool>(false);
    cmd->add_flag("--union", *whole,
                  "judge the mesh whole, as one union: without this, a mesh with solid ids "
                  "(else part ids) is judged solid by solid and solids touching are contacts, "
                  "not defects");
    cmd->add_flag("--no-weld", *no_weld,
                  "do not weld bit-identical vertices; judge the file's own indices");
    cmd->callback([&action, mesh_path, as_json, opts, no_weld, whole] {
        action = [mesh_path, as_json, opts, no_weld, whole] {
            opts->weld = !*no_weld;
            opts->by_solid = !*whole;
            const TriangleMesh mesh = read_mesh(*mesh_path);
            const CheckReport report = check_mesh(mesh, *opts);
            const bool passed = check_passed(report, *opts);
            if (*as_json) {
                auto j = nlohmann::json::parse(check_report_json(report));
                j["file"] = *mesh_path;
                j["passed"] = passed;
                if (const auto faces = defect_faces(mesh, report); !faces.empty()) {
                    auto& list = j["defect_faces"] = nlohmann::json::array();
                    for (const DefectFace& f : faces)
                        list.push_back(
                            {{"part", f.part}, {"face", f.face}, {"defects", f.defects}});
                }
                std::cout << j.dump(2) << "\n";
            } else {
                std::cout << *mesh_path << "\n";
                print_check_report(std::cout, report, 10, &mesh);
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
