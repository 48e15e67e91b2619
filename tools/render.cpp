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

#include <nlohmann/json.hpp>

#include <iostream>
#include <memory>
#include <regex>

namespace seamless::cli {

// INTRACY's failed step 7-9 attempts and single pixels by cause (RenderStats::SplitCause).
nlohmann::json split_causes_json(const RenderStats& st) {
    nlohmann::json j = nlohmann::json::object();
    for (int i = 0; i < RenderStats::split_causes; ++i)
        j[RenderStats::split_cause_names[i]] = {
            {"attempts_failed", st.attempts_failed[i]},
            {"single_pixels", st.single_pixels_by_cause[i]},
            {"certified_pixels", st.certified_pixels_by_cause[i]}};
    return j;
}

nlohmann::json stats_json(const RenderStats& st) {
    nlohmann::json sizes = nlohmann::json::object();
    for (const auto& [size, n] : st.subscreens_by_size) sizes[std::to_string(size)] = n;
    return {{"method", st.method},
            {"width", st.width},
            {"height", st.height},
            {"levels", st.levels},
            {"threads", st.threads},
            {"seconds", st.seconds},
            {"precalc_seconds", st.precalc_seconds},
            {"patches", st.patches},
            {"triangles", st.triangles},
            {"subscreens", st.subscreens},
            {"subscreens_by_size", sizes},
            {"single_pixels", st.single_pixels},
            {"single_pixel_fraction", st.single_pixel_fraction()},
            {"hs_iterations_per_patch", st.hs_iterations_per_patch()},
            {"patches_per_pixel", st.patches_per_pixel()},
            {"primary_rays", st.primary_rays},
            {"background_pixels", st.background_pixels},
            {"secondary_clusters", st.secondary_clusters},
            {"shadowed_clusters", st.shadowed_clusters},
            {"range_enclosures", st.range_enclosures},
            {"enclosures_per_pixel", st.enclosures_per_pixel()},
            {"hs_steps", st.hs_steps},
            {"marks_narrowed", st.marks_narrowed},
            {"mark_bisections", st.mark_bisections},
            {"pixel_patch_solves", st.pixel_patch_solves},
            {"pixel_newton_certified", st.pixel_newton_certified},
            {"split_causes", split_causes_json(st)},
            {"nearest_by_plane", st.nearest_by_plane},
            {"lights_blocked_by_surface", st.lights_blocked_by_surface},
            {"second_order",
             {{"attempts", st.second_order_attempts},
              {"painted", st.second_order_painted},
              {"pixels", st.second_order_pixels}}},
            {"step_seconds",
             {{"narrowing", st.narrow_seconds},
              {"certificate", st.certify_seconds},
              {"shade", st.shade_seconds},
              {"secondary_clusters", st.secondary_seconds},
              {"single_pixels", st.single_pixel_seconds},
              {"certified_pixels", st.certified_pixel_seconds}}},
            {"certified_pixel_fallbacks", st.certified_pixel_fallbacks}};
}

void add_render(CLI::App& app, Action& action) {
    struct Args {
        std::string scene, out, method = "intracy", size, stats;
        int levels = 0, threads = 0;
        bool no_dither = false;
    };
    auto a = std::make_shared<Args>();
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
    cmd->callback([&action, a] {
        action = [a] {
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
                return load_scene(a->scene);
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
                write_text_atomically(files.staging(1), stats_json(st).dump(2) + "\n");
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
