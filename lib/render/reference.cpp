// SPDX-License-Identifier: MIT
// The per-pixel exact reference: the nearest hit of every pixel's primary ray
// by the certified single-ray solve on the projected patches (INTRACY step 6
// for every pixel), shaded as a single pixel.
#include <seamless/render/render.h>

#include <seamless/render/scene/projection.h>
#include <seamless/render/scene/render_loop.h>
#include <seamless/render/shading/shading.h>
#include <seamless/render/tray/trace.h>

#include <atomic>
#include <chrono>
#include <memory>

namespace seamless {

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
                    I = shade_ray(scene, *ts,
                                  {Pw, normalize(ps.frame.to_world_direction(N)),
                                   ps.patches[best].material, best, normalize(ps.frame.eye - Pw)},
                                  0);
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
