// SPDX-License-Identifier: MIT
// seamless render SCENE -o OUT.png: INTRACY, TRAY or the per-pixel reference.
#include "commands.h"
#include "model_options.h"
#include "progress.h"

#include <seamless/base/error.h>
#include <seamless/base/files/atomic_file.h>
#include <seamless/base/files/output_files.h>
#include <seamless/base/parallel/huge_pages.h>
#include <seamless/base/parallel/workers_warm_up.h>
#include <seamless/render/render.h>
#include <seamless/render/scene/render_stats_json.h>

#include <iostream>
#include <memory>
#include <regex>

namespace seamless::cli {

void add_render(CLI::App& app, Action& action) {
    struct Args {
        std::string scene, out, method = "intracy", size, stats;
        int levels = 0, threads = 0;
        bool no_dither = false;
    };
    auto a = std::make_shared<Args>();
    auto limits = std::make_shared<SceneLimits>();
    auto* cmd = app.add_subcommand("render", "Ray trace a scene to PNG with INTRACY (interval "
                                             "screen subdivision), TRAY (one ray per pixel) or "
                                             "the per-pixel exact reference");
    cmd->add_option("SCENE", a->scene, "scene file (JSON, docs/formats.md)")->required();
    cmd->add_option("-o,--output", a->out, "output PNG")->required();
    cmd->add_option("--method", a->method, "intracy | tray | reference")
        ->check(CLI::IsMember({"intracy", "tray", "reference"}))
        ->capture_default_str();
    cmd->add_option("--size", a->size, "image size WxH (default: the scene camera's)");
    cmd->add_option("--levels", a->levels, "intensity levels per channel (default: the scene's)")
        ->check(CLI::Range(2, 65536));
    cmd->add_option("--threads", a->threads, "worker threads (0: all cores; 1: sequential)")
        ->check(CLI::Range(0, 1024))
        ->capture_default_str();
    cmd->add_flag("--no-dither", a->no_dither,
                  "INTRACY paints without dither noise: one level per cluster, or the bilinear "
                  "form within one level of the truth (TRAY: no effect)");
    cmd->add_option("--stats", a->stats, "write run statistics as JSON to this file");
    add_reader_limits(cmd, limits->models);
    cmd->callback([&action, a, limits] {
        action = [a, limits] {
            RenderOptions opt;
            opt.method = a->method == "tray"        ? RenderMethod::tray
                         : a->method == "reference" ? RenderMethod::reference
                                                    : RenderMethod::intracy;
            opt.levels = a->levels;
            opt.threads = a->threads;
            opt.dither = !a->no_dither;
            if (!a->size.empty()) {
                std::smatch m;
                if (!std::regex_match(a->size, m, std::regex(R"((\d+)x(\d+))")))
                    throw InputError("", "--size",
                                     "expected WxH, e.g. 640x480, got '" + a->size + "'");
                // More than five digits is out of range, not a malformed size.
                opt.width = m[1].length() > 5 ? 0 : std::stoi(m[1]);
                opt.height = m[2].length() > 5 ? 0 : std::stoi(m[2]);
                if (opt.width < 1 || opt.height < 1 || opt.width > 16384 || opt.height > 16384)
                    throw InputError("", "--size", "width and height must be in 1..16384");
            }
            // Every output checked (writable, not an input) before the work.
            std::vector<std::filesystem::path> outs{a->out};
            if (!a->stats.empty()) outs.push_back(a->stats);
            OutputFiles files(outs, {a->scene});
            keep_freed_memory(); // the steps reuse each other's pages (huge_pages.h)
            const Scene scene = [&] {
                const WorkersWarmUp warm_up(a->threads); // while the scene is read
                return load_scene(a->scene, *limits);
            }();
            print_warnings(scene.model); // e.g. approximated STEP/IGES surfaces
            std::vector<std::filesystem::path> models;
            for (const SceneObject& o : scene.objects) models.push_back(o.model_path);
            files.refuse_inputs(models);
            ProgressBar bar("render");
            opt.progress = [&bar](double f) { bar.update(f); };
            RenderStats st;
            const Image im = render(scene, opt, &st);
            bar.finish();
            write_png(files.staging(0), im);
            if (!a->stats.empty())
                write_text_atomically(files.staging(1), render_stats_json(st) + "\n");
            files.commit(); // both outputs, or neither
            std::cout << st.method << ": " << st.width << "x" << st.height << ", " << st.levels
                      << " levels, " << st.seconds << " s, single-pixel fraction "
                      << st.single_pixel_fraction() << ", " << st.primary_rays
                      << " primary rays -> " << a->out << "\n";
            return 0;
        };
    });
}

} // namespace seamless::cli
