// SPDX-License-Identifier: MIT
// seamless sweep MODEL...: accuracy against run time (paper section 8). Either
// the planarity tolerances eps1 = f * 0.001 d_max, eps2 = f * 0.02 d_max or
// (--tolerance) a requested deviation D = f * 0.001 d_max, over decades of f
// (sweep_tolerances in lib/mesh/deviation/sweep.h); every row sets the certified bound
// beside the measured deviation. Prints one line per row, or JSON. The report
// of docs/results/tessellation.md is written by bench/tessellation.
// Exit status 1 when a measured deviation exceeds its bound.
#include "commands.h"
#include "model_options.h"
#include "number_options.h"

#include <seamless/base/files/atomic_file.h>
#include <seamless/mesh/deviation/sweep.h>
#include <seamless/model/model.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <iostream>
#include <memory>

namespace seamless::cli {

void add_sweep(CLI::App& app, Action& action) {
    auto* cmd = app.add_subcommand(
        "sweep", "Error against run time: tessellate at tolerances scaled over decades, "
                 "measure the deviation from the exact surfaces, compare with the bound");
    struct Args {
        std::vector<std::string> models;
        int decades = 5, steps = 2, threads = 0;
        double first = 1;
        long long max_triangles = 2'000'000;
        bool tolerance = false;
        std::string json;
    };
    auto args = std::make_shared<Args>();
    auto load = std::make_shared<ModelLoadOptions>();
    cmd->add_option("MODEL", args->models,
                    "model files (.json, Newell .bpt, STEP, IGES; B-rep models sweep the deviation "
                    "D = f * 0.001 of their diagonal)")
        ->required();
    cmd->add_option("--first-decade", args->first, "start at f = 10^N (default 1: f = 10)")
        ->check(finite_number(Bound::any));
    cmd->add_option("--decades", args->decades, "decades of f to sweep")->check(CLI::Range(0, 12));
    cmd->add_option("--steps-per-decade", args->steps, "steps per decade")
        ->check(CLI::Range(1, 20));
    cmd->add_option("--max-triangles", args->max_triangles,
                    "stop a model before a step predicted to exceed this many triangles")
        ->check(finite_number(Bound::positive));
    cmd->add_option("--threads", args->threads,
                    "worker threads of the tessellation and the deviation measurement (0: all)")
        ->check(CLI::Range(0, 1024));
    cmd->add_flag("--tolerance", args->tolerance,
                  "request the deviation D = f * 0.001 d_max instead of scaling the planarity "
                  "tolerances");
    cmd->add_option("--json", args->json, "write the rows as JSON to this file ('-': stdout)");
    add_reader_limits(cmd, *load);
    cmd->callback([&action, args, load] {
        action = [args, load] {
            SweepOptions opt;
            opt.tolerance = args->tolerance;
            opt.first_decade = args->first;
            opt.decades = args->decades;
            opt.steps_per_decade = args->steps;
            opt.max_triangles = args->max_triangles;
            opt.threads = args->threads;
            opt.deviation.threads = args->threads;
            const bool to_stdout = args->json == "-";
            std::ostream& text = to_stdout ? std::cerr : std::cout;
            nlohmann::json all = nlohmann::json::array();
            bool ok = true;
            for (const std::string& path : args->models) {
                const Model m = load_model(path, *load);
                text << std::filesystem::path(path).stem().string() << ":\n";
                // Each row printed as soon as it is measured.
                opt.on_row = [&](const SweepRow& r) {
                    text << "  f " << r.factor << ": " << r.tess.triangles << " triangles, "
                         << r.tess.seconds << " s, bound " << r.tess.max_error_bound
                         << ", measured " << r.deviation.max() << " (measured/bound "
                         << r.tightness() << ")" << (r.within_bound() ? "" : "  EXCEEDS THE BOUND")
                         << std::endl;
                    ok = ok && r.within_bound();
                };
                const std::vector<SweepRow> rows = sweep_tolerances(m, opt);
                all.push_back({{"model", path},
                               {"d_max", d_max(m)},
                               {"rows", nlohmann::json::parse(sweep_json(rows))}});
            }
            if (to_stdout)
                std::cout << all.dump(2) << "\n";
            else if (!args->json.empty())
                write_text_atomically(args->json, all.dump(2) + "\n");
            return ok ? 0 : 1;
        };
    });
}

} // namespace seamless::cli
