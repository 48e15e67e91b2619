// SPDX-License-Identifier: MIT
#include <seamless/render/parallel.h>
#include <seamless/render/render.h>

#include <seamless/render/projection.h>
#include <seamless/render/shading.h>
#include <seamless/render/trace.h>

#include <atomic>
#include <chrono>
#include <memory>

namespace seamless {

void RenderStats::merge(const RenderStats& o) {
    for (const auto& [size, n] : o.subscreens_by_size) subscreens_by_size[size] += n;
    subscreens += o.subscreens;
    single_pixels += o.single_pixels;
    pixel_patch_solves += o.pixel_patch_solves;
    pixel_newton_certified += o.pixel_newton_certified;
    hs_iterations += o.hs_iterations;
    primary_rays += o.primary_rays;
    background_pixels += o.background_pixels;
    secondary_clusters += o.secondary_clusters;
    shadowed_clusters += o.shadowed_clusters;
    range_enclosures += o.range_enclosures;
    hs_steps += o.hs_steps;
    marks_narrowed += o.marks_narrowed;
    mark_bisections += o.mark_bisections;
    narrow_seconds += o.narrow_seconds;
    certify_seconds += o.certify_seconds;
    shade_seconds += o.shade_seconds;
    secondary_seconds += o.secondary_seconds;
    single_pixel_seconds += o.single_pixel_seconds;
    nearest_by_plane += o.nearest_by_plane;
    lights_blocked_by_surface += o.lights_blocked_by_surface;
    second_order_attempts += o.second_order_attempts;
    second_order_painted += o.second_order_painted;
    second_order_pixels += o.second_order_pixels;
    certified_pixel_fallbacks += o.certified_pixel_fallbacks;
    certified_pixel_seconds += o.certified_pixel_seconds;
    for (int i = 0; i < split_causes; ++i) {
        attempts_failed[i] += o.attempts_failed[i];
        single_pixels_by_cause[i] += o.single_pixels_by_cause[i];
        certified_pixels_by_cause[i] += o.certified_pixels_by_cause[i];
    }
}

Image render(const Scene& scene, const RenderOptions& opt, RenderStats* stats) {
    RenderStats local;
    RenderStats& st = stats ? *stats : local;
    st = RenderStats{};
    st.width = opt.width > 0 ? opt.width : scene.camera.width;
    st.height = opt.height > 0 ? opt.height : scene.camera.height;
    st.levels = opt.levels > 0 ? opt.levels : scene.levels;
    st.threads = opt.threads;
    const auto t0 = std::chrono::steady_clock::now();
    Image im;
    switch (opt.method) {
    case RenderMethod::intracy:
        st.method = "intracy";
        im = render_intracy(scene, opt, st);
        break;
    case RenderMethod::tray:
        st.method = "tray";
        im = render_tray(scene, opt, st);
        break;
    case RenderMethod::reference:
        st.method = "reference";
        im = render_reference(scene, opt, st);
        break;
    }
    st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return im;
}

Image render_reference(const Scene& scene, const RenderOptions& opt, RenderStats& st) {
    const int W = opt.width > 0 ? opt.width : scene.camera.width;
    const int H = opt.height > 0 ? opt.height : scene.camera.height;
    const int L = opt.levels > 0 ? opt.levels : scene.levels;
    const ProjectedScene ps = project_scene(scene, W, H);
    st.patches = static_cast<long long>(ps.patches.size());
    // Secondary rays go against the triangles, as in INTRACY and TRAY.
    std::unique_ptr<TriangleScene> ts;
    if (needs_secondary_rays(scene)) {
        ts = std::make_unique<TriangleScene>(build_triangle_scene(scene, opt.threads));
        st.triangles = ts->tess.mesh.triangle_count();
    }
    Image image(W, H, L);
    // Whole-patch screen rectangles for the hull comparison.
    struct Rect {
        Interval a, b;
        bool valid;
    };
    std::vector<Rect> rects;
    for (const ProjectedPatch& pp : ps.patches) {
        const IVec3 P = enclose_point(pp.forms, ParamBox{});
        const bool valid = P[2].lo() > 0;
        rects.push_back({valid ? P[0] / P[2] : Interval::entire(),
                         valid ? P[1] / P[2] : Interval::entire(), valid});
    }
    render_rows(W, H, opt, st, [&](int y, RenderStats& rs) {
        std::vector<RayPatchHit> hits;
        const double b = ps.frame.screen_b(y + 0.5);
        for (int x = 0; x < W; ++x) {
            const double a = ps.frame.screen_a(x + 0.5);
            const Ray ray = ProjectedScene::primary_ray(a, b);
            ++rs.primary_rays;
            ++rs.single_pixels;
            double best_q = std::numeric_limits<double>::infinity();
            int best = -1;
            double bs = 0, bt = 0;
            for (size_t k = 0; k < ps.patches.size(); ++k) {
                if (rects[k].valid && (!rects[k].a.contains(a) || !rects[k].b.contains(b)))
                    continue;
                hits.clear();
                RayPatchStats hs;
                intersect(ps.patches[k].forms, ray, hits, RayPatchOptions{}, &hs);
                ++rs.pixel_patch_solves;
                rs.hs_iterations += hs.iterations;
                auto h = nearest_hit(hits, 0.0);
                if (!h || !(h->q.hi() > 0)) continue;
                if (std::max(h->q.lo(), 0.0) < best_q) {
                    best_q = std::max(h->q.lo(), 0.0);
                    best = static_cast<int>(k);
                    bs = h->box.s.mid();
                    bt = h->box.t.mid();
                }
            }
            std::array<double, 3> I;
            if (best < 0) {
                I = {ps.lighting.background.x, ps.lighting.background.y, ps.lighting.background.z};
                ++rs.background_pixels;
            } else {
                Vec3 P, N;
                surface_frame(ps.patches[best].patch, bs, bt, P, N);
                if (ts) {
                    const Vec3 Pw = ps.frame.to_world(P);
                    I = shade_ray(scene, *ts, Pw, normalize(ps.frame.to_world_direction(N)),
                                  ps.patches[best].material, best, normalize(ps.frame.eye - Pw), 0);
                } else {
                    I = shade<double>(ps.lighting, ps.lighting.materials[ps.patches[best].material],
                                      to_v3(P), to_v3(N), Vec3{});
                }
            }
            for (int c = 0; c < 3; ++c)
                image.at(x, y, c) = static_cast<std::uint16_t>(quantise(I[c], L));
            image.surface_at(x, y) = best >= 0;
        }
    });
    return image;
}

} // namespace seamless
