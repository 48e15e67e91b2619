// SPDX-License-Identifier: MIT
// TRAY, the "conventional" baseline of paper section 8: the screen is shaded
// pixel by pixel, one primary ray through each pixel centre intersected with the
// triangles of the crack-free tessellation, found by the hull comparison on the
// binary patch trees (Proposition 11, remarks 1-2). Everything is in world
// space: the rays start at the camera's eye and the scene's lights are used as
// they are; shading is the same shade<double>() as INTRACY's, at the hit point
// on the triangle with the exact surface normals of its corners interpolated.
#include <seamless/render/render.h>

#include <seamless/render/camera.h>
#include <seamless/render/ray_triangle.h>
#include <seamless/render/shading.h>
#include <seamless/tessellate/tessellation.h>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>
#include <limits>

namespace seamless {

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
    const Tessellation tess = tessellate(scene.model);
    st.precalc_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const TriangleMesh& mesh = tess.mesh;
    st.patches = static_cast<long long>(tess.trees.roots.size());
    st.triangles = mesh.triangle_count();

    Image image(W, H, L);
    std::vector<RenderStats> row_stats(H);
    std::atomic<int> done{0};
    auto row = [&](int y) {
        RenderStats& rs = row_stats[y];
        const double b = frame.screen_b(y + 0.5);
        for (int x = 0; x < W; ++x) {
            const TriangleRay ray(frame.eye, frame.ray_direction(frame.screen_a(x + 0.5), b));
            ++rs.primary_rays;
            ++rs.single_pixels;
            // Nearest hit; hulls beyond it are pruned. Ties keep the first triangle in
            // traversal order, which is fixed, so the image does not depend on threads.
            double best_t = std::numeric_limits<double>::infinity();
            int best = -1;
            RayTriangleHit best_hit, h;
            visit_candidate_triangles(
                tess.trees, [&](const Box3& box) { return ray_hits_box(ray, box, best_t); },
                [&](int f) {
                    // pixel_patch_solves counts ray-triangle tests for TRAY: the
                    // single-ray solves of Proposition 11 play the part of the
                    // pixel x patch Hansen-Sengupta solves of INTRACY.
                    ++rs.pixel_patch_solves;
                    const auto& tri = mesh.triangles[f];
                    if (intersect_triangle(ray, mesh.positions[tri[0]], mesh.positions[tri[1]],
                                           mesh.positions[tri[2]], best_t, h)) {
                        best_t = h.t;
                        best = f;
                        best_hit = h;
                    }
                });
            std::array<double, 3> I;
            if (best < 0) {
                I = {scene.background.x, scene.background.y, scene.background.z};
                ++rs.background_pixels;
            } else {
                const auto& tri = mesh.triangles[best];
                const auto& n = mesh.corner_normals[best];
                const RayTriangleHit& w = best_hit;
                const Vec3 P = w.b0 * mesh.positions[tri[0]] + w.b1 * mesh.positions[tri[1]] +
                               w.b2 * mesh.positions[tri[2]];
                Vec3 N = w.b0 * n[0] + w.b1 * n[1] + w.b2 * n[2];
                // Corner normals that cancel (never seen, but possible): the facet's own.
                if (!(dot(N, N) > 0))
                    N = cross(mesh.positions[tri[1]] - mesh.positions[tri[0]],
                              mesh.positions[tri[2]] - mesh.positions[tri[0]]);
                const int surface = mesh.triangle_surface[best];
                I = shade<double>(scene, scene.materials[scene.surface_material[surface]], to_v3(P),
                                  to_v3(N), frame.eye);
            }
            for (int c = 0; c < 3; ++c)
                image.at(x, y, c) = static_cast<std::uint16_t>(quantise(I[c], L));
            image.surface_at(x, y) = best >= 0;
        }
        const int d = ++done;
        if (opt.progress && d % std::max(1, H / 100) == 0) opt.progress(static_cast<double>(d) / H);
    };
    if (opt.threads == 1) {
        for (int y = 0; y < H; ++y) row(y);
    } else {
        tbb::task_arena arena(opt.threads > 0 ? opt.threads : tbb::task_arena::automatic);
        arena.execute([&] { tbb::parallel_for(0, H, row); });
    }
    for (const RenderStats& s : row_stats) st.merge(s);
    st.subscreens_by_size[1] = static_cast<long long>(W) * H;
    return image;
}

} // namespace seamless
