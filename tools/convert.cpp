// SPDX-License-Identifier: MIT
// seamless convert MODEL -o OUT.json: any model the program reads (STEP, IGES,
// .bpt, JSON) as a JSON model: version 1 (surfaces), or version 2 when the
// model is a B-rep (trimmed faces).
#include "commands.h"
#include "model_options.h"

#include <seamless/base/error.h>
#include <seamless/base/files/atomic_file.h>
#include <seamless/base/files/output_files.h>
#include <seamless/model/model.h>

#include <cctype>
#include <filesystem>
#include <iostream>
#include <memory>

namespace seamless::cli {

void add_convert(CLI::App& app, Action& action) {
    auto* cmd = app.add_subcommand(
        "convert", "Write a model (STEP, IGES, .bpt or JSON) as a JSON model (version 2 with "
                   "its B-rep when it has trimmed faces)");
    struct Args {
        std::string model, out;
        ModelLoadOptions load;
    };
    auto args = std::make_shared<Args>();
    cmd->add_option("MODEL", args->model,
                    "model file (.json, Newell .bpt, STEP .step/.stp, IGES .iges/.igs)")
        ->required();
    cmd->add_option("-o,--output", args->out, "JSON model file to write (.json)")->required();
    add_model_options(cmd, args->load);
    cmd->add_flag("--keep-assembly", args->load.keep_assembly,
                  "write a STEP/IGES assembly as its tree: each part once in its own "
                  "coordinates, with its instances' placements (default: every instance placed)");
    cmd->callback([&action, args] {
        action = [args] {
            std::string ext = std::filesystem::path(args->out).extension().string();
            for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
            if (ext != ".json")
                throw InputError(args->out, "",
                                 "unknown model extension '" + ext + "' (convert writes .json)");
            // The output checked (writable, not the input) before the work.
            OutputFiles files({args->out}, {args->model});
            const Model m = load_model(args->model, args->load);
            print_warnings(m);
            write_text_atomically(files.staging(0), to_json(m));
            files.commit();
            size_t approximated = 0;
            for (const SurfaceOrigin& o : m.origins) approximated += o.exact ? 0 : 1;
            std::cout << m.surfaces.size() << " surface" << (m.surfaces.size() == 1 ? "" : "s");
            if (!m.origins.empty())
                std::cout << " (" << m.surfaces.size() - approximated << " exact, " << approximated
                          << " approximated)";
            if (!m.brep.empty())
                std::cout << ", " << m.brep.faces.size() << " B-rep face"
                          << (m.brep.faces.size() == 1 ? "" : "s");
            std::cout << " -> " << args->out << "\n";
            return 0;
        };
    });
}

} // namespace seamless::cli
