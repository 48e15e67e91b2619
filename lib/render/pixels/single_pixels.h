// SPDX-License-Identifier: MIT
// INTRACY step 6 (paper section 7): a one-pixel sub-screen B is solved on
// every marked patch, nearest first (remark 1), by certified Newton with the
// covering method as the fallback (pixel_solve.h), and shaded at its hit
// (pixel_shade.h); so is every pixel of a B of at most
// RenderOptions::pixel_subscreen pixels, without a cluster attempt: a few
// certified Newton solves cost less than narrowing, certificate and SHADE
// for a cluster of a handful of pixels.
#pragma once

#include <seamless/render/pixels/pixel_solve.h>
#include <seamless/render/scene/canvas.h>
#include <seamless/render/scene/projection.h>
#include <seamless/render/scene/render_stats.h>
#include <seamless/render/scene/scene.h>
#include <seamless/render/subscreen/shared_marks.h>
#include <seamless/render/subscreen/subscreen.h>
#include <seamless/render/tray/trace.h>

#include <vector>

namespace seamless {

class SinglePixels {
  public:
    // ts: null when no secondary rays are in play.
    SinglePixels(const ProjectedScene& ps, const Scene& scene, const TriangleScene* ts,
                 const Canvas& canvas)
        : ps_(ps), scene_(scene), ts_(ts), canvas_(canvas) {}

    // Step 6 for the one pixel of B on its n marks.
    void paint_pixel(const SubScreen& B, const Mark* marks, size_t n, PixelScratch& scratch,
                     RenderStats& st);

    // Step 6 for every pixel of a small B, from B's marks in `stack` (those
    // of its parent), shared by its pixels: one Jacobian per mark, Newton's
    // starting points and the bisections of marks a silhouette crosses
    // (SharedMarks of shared_marks.h, appended to stack.coefs past B.coef_end).
    void paint_subscreen(const SubScreen& B, MarkStack& stack, PixelScratch& scratch,
                         RenderStats& st);

  private:
    // A pixel of a small B: its hit, the point and normal there (camera
    // coordinates), and the first pixel of B hitting the same patch.
    struct Shaded {
        PixelHit hit;
        Vec3 P, N;
        int group = -1;
    };
    Shaded solve(double a, double b, PixelScratch& scratch, RenderStats& st);
    void share_lights();
    void paint_hit(int x, int y, int cause, const PixelHit& h, RenderStats& st,
                   const Shaded* shaded = nullptr);

    const ProjectedScene& ps_;
    const Scene& scene_;
    const TriangleScene* ts_; // null: no secondary rays in play
    const Canvas& canvas_;
    SharedMarks shared_;           // paint_subscreen: the marks of a small B
    std::vector<Shaded> hits_;     // paint_subscreen: B's hits, row by row
    std::vector<char> lit_;        // share_lights: per hits_ index (a group's first), per light
    std::vector<int> light_hints_; // share_lights: per light, the last triangle that may block it
};

} // namespace seamless
