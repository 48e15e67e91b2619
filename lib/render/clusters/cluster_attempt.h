// SPDX-License-Identifier: MIT
// The cluster attempt of INTRACY (paper section 7, steps 7 to 9) for a
// sub-screen B that is not thin, with its marks narrowed (step 3):
//  step 7: if the nearest marked patch is q-separated from all the others (a
//          nearest q-connected set, Theorem 10 remark 4), or lies before a
//          plane that the others lie beyond, and the Hansen-Sengupta operator
//          over the whole cluster maps its box into its interior (Theorem 6 iii
//          for every ray of B at once: each ray hits it, exactly once in the
//          box), then every ray of B sees that patch and nothing else;
//  step 8: SHADE encloses the intensity of B over the hulls of point and normal
//          (cluster_shade.h);
//  step 9: if every channel's enclosure holds at most two levels, B is painted
//          with the bilinear form of its four corner intensities (corner rays by
//          Newton, remark 2) plus dither in [-0.5, 0.5], kept within the
//          enclosure's levels; without dithering B must hold one level. Where
//          the enclosure spans more, a second-order bound (second_order.h) may
//          still prove the bilinear form within one level of the truth.
// Step 7's certificate replaces the paper's conditions a)-c) of remark 4 with a
// proof: a pixel painted from a cluster is never wrong by more than one level
// (the enclosure holds the true intensity).
#pragma once

#include <seamless/render/clusters/cluster_shade.h>
#include <seamless/render/pixels/pixel_solve.h>
#include <seamless/render/scene/canvas.h>
#include <seamless/render/scene/image.h>
#include <seamless/render/scene/projection.h>
#include <seamless/render/scene/render_options.h>
#include <seamless/render/scene/render_stats.h>
#include <seamless/render/subscreen/mark.h>
#include <seamless/render/subscreen/primary_cluster.h>
#include <seamless/render/tray/trace.h>

#include <array>
#include <cstddef>
#include <vector>

namespace seamless {

// What an attempt came to.
struct ClusterAttemptResult {
    int cause = -1;      // -1: B was painted; else why not (RenderStats::SplitCause)
    int levels_over = 0; // step 9's widest enclosure in levels (0: not reached)
    // Step 7 proven, B not painted (cause light or span): every ray of B hits
    // `patch` exactly once in `box` and nothing nearer (certified_pixels.h).
    bool proven = false;
    int patch = -1;
    ParamBox box{};
};

class ClusterAttempt {
  public:
    // ts, neighbours: as ClusterShader's. Paints into image with `levels`.
    ClusterAttempt(const ProjectedScene& ps, const Scene& scene, const TriangleScene* ts,
                   const std::vector<int>* neighbours, const RenderOptions& opt, Image& image,
                   int levels);

    // Steps 7 to 9 for B with its n marks (subpatches in `coefs`); `pixel`:
    // scratch for corner rays and the second-order rule.
    ClusterAttemptResult try_paint(const PixelRect& B, const Mark* marks, size_t n,
                                   const SubpatchArena& coefs, PixelScratch& pixel,
                                   RenderStats& st);

  private:
    // B's marks and their subpatches.
    struct MarkSpan {
        const Mark* marks;
        size_t n;
        const SubpatchArena& coefs;
    };
    // Step 7's cluster: the nearest patch and its box, certified by
    // certify(): every ray of B hits `patch` exactly once in `box`; e, world:
    // the enclosures of the hits (camera and world coordinates) and of the
    // patch's derivatives there.
    struct Certified {
        int patch = -1;
        ParamBox box{};
        PatchEnclosure e;
        IVec3 world;
    };
    int nearest_patch(const Mark* marks, size_t n, ParamBox& box) const;
    int certify(const PixelRect& B, const MarkSpan& m, Certified& c, RenderStats& st);
    bool enclose_hits(const MarkSpan& m, Certified& c);
    int nearest_cause(const MarkSpan& m, const Certified& c, Interval a, Interval b,
                      RenderStats& st) const;
    int certificate_cause(const Mark* marks, size_t n) const;
    bool corner_misses(const PixelRect& B, const MarkSpan& m, int patch, bool clip) const;
    bool second_order_corners(const PixelRect& B, const Certified& c, const ClusterShading& cs,
                              PixelScratch& pixel, RenderStats& st, int& levels_over,
                              std::array<double, 3> corner[4]);
    void corner_rays(const PixelRect& B, const Certified& c, const std::array<Interval, 3>& I,
                     PixelScratch& pixel, RenderStats& st, std::array<double, 3> corner[4]);
    void paint_level(const PixelRect& B, const int lo[3]);
    void paint_bilinear(const PixelRect& B, const std::array<double, 3> corner[4], const int lo[3],
                        const int hi[3]);

    static constexpr long long kSecondOrderArea = 32; // smallest B for step 9's second order

    const ProjectedScene& ps_;
    const Scene& scene_;
    const TriangleScene* ts_; // null: no secondary rays in play
    bool dither_;             // RenderOptions::dither
    Image& image_;
    int levels_;
    ClusterShader shader_;
    ClusterSystem sys_;
    std::vector<Interval> restricted_; // a mark's subpatch over the certified box
};

} // namespace seamless
