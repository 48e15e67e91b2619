// SPDX-License-Identifier: MIT
#include <seamless/render/scene/projection.h>

#include <seamless/model/model.h>
#include <seamless/render/scene/render_loop.h>
#include <seamless/render/tray/trace.h>

namespace seamless {

namespace {

// sum_ij |coefficient (i, j) of component c|, rounded up: |f_c| <= it on [0,1]^2.
double coefficient_magnitude(const PowerForm& f, int c) {
    Interval m(0.0);
    for (int i = 0; i <= f.p; ++i)
        for (int j = 0; j <= f.q; ++j) m = m + Interval(f.at(c, i, j).mag());
    return m.hi();
}

} // namespace

void set_camera_patch(ProjectedPatch& pp, const BezierPatch& b) {
    pp.patch = b;
    patch_forms(b, pp.forms);
    pp.hull = enclose_point(pp.forms, ParamBox{});
    for (int c = 0; c < 4; ++c) pp.slope_s[c] = pp.slope_t[c] = 0;
    for (int c = 0; c < (pp.forms.rational ? 4 : 3); ++c) {
        pp.slope_s[c] = coefficient_magnitude(pp.forms.Xs, c);
        pp.slope_t[c] = coefficient_magnitude(pp.forms.Xt, c);
    }
    pp.shape = subpatch_shape(b);
}

ProjectedScene project_scene(const Scene& scene, int width, int height, int threads) {
    return project_scene(scene, bezier_patches(scene.model), width, height, threads);
}

ProjectedScene project_scene(const Scene& scene, const std::vector<BezierPatch>& patches, int width,
                             int height, int threads) {
    Camera cam = scene.camera;
    cam.width = width;
    cam.height = height;
    ProjectedScene ps(cam);
    ps.lighting.ambient = scene.ambient;
    ps.lighting.background = scene.background;
    ps.lighting.materials = scene.materials;
    ps.lighting.levels = scene.levels;
    for (const Light& l : scene.lights)
        if (l.on()) ps.lighting.lights.push_back({ps.frame.to_camera(l.position), l.color});
    // Each ProjectedPatch (9.8 KB up to bicubic) constructed in place by its
    // worker, once, in parallel; never copied or moved.
    ps.patches.reset(patches.size());
    for_each_item(static_cast<int>(patches.size()), threads, [&](int i) {
        ProjectedPatch& pp = ps.patches.place(i);
        BezierPatch b = patches[i];
        for (int u = 0; u <= b.p; ++u)
            for (int v = 0; v <= b.q; ++v) b.at(u, v) = ps.frame.to_camera(b.at(u, v));
        set_camera_patch(pp, b);
        pp.material = scene.surface_material[b.surface];
    });
    return ps;
}

void surface_frame(const BezierPatch& b, double s, double t, Vec3& point, Vec3& normal,
                   SurfacePoint* at) {
    const SurfacePoint sp = evaluate(b, s, t);
    if (at) *at = sp;
    surface_frame(b, s, t, sp, point, normal);
}

void surface_frame(const BezierPatch& b, double s, double t, const SurfacePoint& sp, Vec3& point,
                   Vec3& normal) {
    point = sp.point;
    normal = sp.normal();
    // At a collapsed edge the normal vanishes; take it a little way inside.
    for (double h = 1e-7; norm(normal) <= 1e-14 * (norm(sp.du) + norm(sp.dv) + 1e-300) && h < 0.1;
         h *= 10) {
        SurfacePoint q = evaluate(b, s + (s < 0.5 ? h : -h), t + (t < 0.5 ? h : -h));
        normal = q.normal();
    }
}

} // namespace seamless
