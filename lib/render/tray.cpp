// SPDX-License-Identifier: MIT
// TRAY, the "conventional" baseline of paper section 8: the screen is shaded
// pixel by pixel, one primary ray through each pixel centre intersected with the
// triangles of the crack-free tessellation, found by the hull comparison on the
// binary patch trees (Proposition 11, remarks 1-2), then shaded by SHADE for
// one ray (trace.h): shadow rays, reflection and refraction over the same
// triangles, with the same shade<double>() as INTRACY's at the hit point on the
// triangle with the exact surface normals of its corners interpolated.
// Everything is in world space.
#include <seamless/render/render.h>
#include <seamless/render/scene/render_loop.h>

#include <seamless/render/scene/camera.h>
#include <seamless/render/shading/shading.h>
#include <seamless/render/tray/trace.h>

#include <atomic>
#include <chrono>
#include <limits>

namespace seamless {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
} // namespace

Image render_tray(const Scene& scene, const RenderOptions& opt, RenderStats& st) {
    const int W = opt.width > 0 ? opt.width : scene.camera.width;
    const int H = opt.height > 0 ? opt.height : scene.camera.height;
    const int L = opt.levels > 0 ? opt.levels : scene.levels;
    Camera cam = scene.camera;
    cam.width = W;
    cam.height = H;
    const CameraFrame frame(cam);

    // Precalculation (INTRACY step 1 / Table 1): the paper's default tolerances,
    // eps from d_max of the whole scene.
    const auto t0 = std::chrono::steady_clock::now();
    const TriangleScene ts = build_triangle_scene(scene, opt.threads);
    st.precalc_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    st.patches = static_cast<long long>(ts.tess.trees.roots.size());
    st.triangles = ts.tess.mesh.triangle_count();

    // Every pixel is written below, by the worker of its row: no clearing pass.
    Image image(W, H, L, Image::Unfilled{});
    render_rows(W, H, opt, st, [&](int y, RenderStats& rs) {
        const double b = frame.screen_b(y + 0.5);
        for (int x = 0; x < W; ++x) {
            const Vec3 ray_origin = frame.eye;
            const Vec3 dir = frame.ray_direction(frame.screen_a(x + 0.5), b);
            ++rs.primary_rays;
            ++rs.single_pixels;
            // Nearest hit; hulls beyond it are pruned. Ties keep the first triangle in
            // traversal order, which is fixed, so the image does not depend on threads.
            // pixel_patch_solves counts ray-triangle tests for TRAY (primary, shadow and
            // secondary rays): the single-ray solves of Proposition 11 play the part of
            // the pixel x patch Hansen-Sengupta solves of INTRACY.
            TraceHit hit;
            std::array<double, 3> I;
            if (!nearest_hit(ts, {ray_origin, dir, 0, kInf, -1}, hit, &rs.pixel_patch_solves)) {
                I = {scene.background.x, scene.background.y, scene.background.z};
                ++rs.background_pixels;
            } else {
                I = shade_ray(scene, ts,
                              {hit.point, hit.normal, hit.material, hit.patch, -normalize(dir)}, 0,
                              &rs.pixel_patch_solves);
            }
            for (int c = 0; c < 3; ++c)
                image.at(x, y, c) = static_cast<std::uint16_t>(quantise(I[c], L));
            image.surface_at(x, y) = hit.triangle >= 0;
        }
    });
    return image;
}

} // namespace seamless
