// SPDX-License-Identifier: MIT
// The pixels of a certified cluster (paper section 7, step 7 proven, steps 8
// or 9 failed): every ray of a sub-screen B hits patch `patch` exactly once in
// the parameter box `box`, and no other marked patch nearer (Theorem 6 iii for
// every ray of B at once, with the nearest q-connected set of Theorem 10
// remark 4). Where SHADE's enclosure over B is undecided (a light, cause
// light) or too wide (step 9, cause span), the paper splits B and solves its
// pieces again from scratch; a small B is better painted pixel by pixel from
// the certificate it already has: per pixel, Newton in doubles on `patch`
// inside `box` from the neighbouring pixel's (s, t), then SHADE for that one
// ray at the hit, as a single pixel of step 6 is shaded (shadow rays only for
// the lights not proven to reach a tile's hits). Where Newton does not
// converge inside `box` the pixel is solved by certified Newton on the one
// mark (patch, box) (solve_pixel of pixel_solve.h), as a corner ray is.
//
// Why this is as certified as a single pixel: the certificate proves that the
// ray of each pixel of B has exactly one zero of G = (X - aZ, Y - bZ) in box
// and that it is the nearest hit of the ray; Newton converging inside box
// (newton_in_box of certified_newton.h: a step below 1e-9, or one whose
// successor would be below 1e-12) can only have converged to that zero; the shading is in doubles
// at the hit, as for every single pixel and corner ray (shade_at of
// pixel_shade.h, with shadow rays for the lights).
#pragma once

#include <seamless/render/clusters/cluster_attempt.h>
#include <seamless/render/pixels/certified_newton.h>
#include <seamless/render/pixels/pixel_solve.h>
#include <seamless/render/scene/image.h>
#include <seamless/render/scene/projection.h>
#include <seamless/render/scene/render_options.h>
#include <seamless/render/scene/render_stats.h>
#include <seamless/render/subscreen/mark.h>
#include <seamless/render/tray/trace.h>

#include <vector>

namespace seamless {

class CertifiedPixels {
  public:
    CertifiedPixels(const ProjectedScene& ps, const Scene& scene, const TriangleScene* ts,
                    Image& image, int levels)
        : ps_(ps), scene_(scene), ts_(ts), image_(image), levels_(levels) {}

    // Paints every pixel of B, whose step 7 certificate r holds (r.proven);
    // counts them under r.cause (RenderStats::certified_pixels_by_cause).
    // marks, n: B's marks, for a ray that the one mark (r.patch, r.box) leaves
    // without a hit (none, by step 7's proof): then it is solved as step 6's.
    void paint(const PixelRect& B, const ClusterAttemptResult& r, const Mark* marks, size_t n,
               PixelScratch& scratch, RenderStats& st);

  private:
    // B is painted in tiles: a tile's hits on the certified patch share one
    // certificate per light (lights_reaching_box of pixel_lights.h), where
    // SHADE's for all of B failed; 8 x 4 took the fewest instructions on
    // scenes 2 and 3 (docs/results/render.md).
    static constexpr int kTileWidth = 8, kTileHeight = 4;

    struct Shaded { // a pixel's hit, with point and normal there (camera coordinates)
        PixelHit hit;
        Vec3 P, N;
    };
    struct Marks { // B's marks
        const Mark* marks;
        size_t n;
    };
    struct Starts { // where Newton starts: the last hit, the row's first, the next
        NewtonRun *last, *row, *next;
    };
    int solve_tile(const PixelRect& tile, const ClusterAttemptResult& r, const Marks& marks,
                   Starts& runs, IVec<3>& Pw, PixelScratch& scratch, RenderStats& st);
    void shade_tile(const PixelRect& tile, int patch, bool shared, RenderStats& st);

    const ProjectedScene& ps_;
    const Scene& scene_;
    const TriangleScene* ts_;
    Image& image_;
    int levels_;
    std::vector<Shaded> hits_; // a tile's, row by row
    std::vector<char> lit_;    // per light: reaches every hit of the tile (pixel_lights.h)
    std::vector<int> hints_;   // lights_reaching_box's
};

} // namespace seamless
