// SPDX-License-Identifier: MIT
// Single primary rays against marked patches: INTRACY step 6 (a one-pixel
// sub-screen, remark 1: the nearest intersection) and the corner rays of step
// 9 (remark 2).
//
// Each ray is solved on each marked patch by certified Newton
// (certified_newton.h). Where that leaves a box undecided, the part one
// Hansen-Sengupta step leaves is tried again, halved when it did not shrink
// much, and only boxes still undecided after a few rounds take the full
// covering method of ray_patch.h. The pixels of a small sub-screen
// (SharedMarks) share A per mark (enclosed for all of their rays), computed
// when the first of them needs it; Newton runs on the mark's whole box from
// the (s, t) where the previous pixel hit the same mark, and only where that
// certifies no hit does the ray clip the mark's subpatch (a certain miss, or a
// smaller box for the steps above).
#pragma once

#include <seamless/render/pixels/certified_newton.h>
#include <seamless/render/scene/projection.h>
#include <seamless/render/scene/render_options.h>
#include <seamless/render/scene/render_stats.h>
#include <seamless/render/subscreen/mark.h>
#include <seamless/render/subscreen/primary_cluster.h>

#include <seamless/interval/hansen_sengupta.h>

#include <array>
#include <limits>
#include <span>
#include <utility>
#include <vector>

namespace seamless {

class SharedMarks; // shared_marks.h

struct PixelHit {
    int patch = -1; // -1: the ray certainly misses every marked patch
    double s = 0, t = 0, q = 0;
    int candidates = 0; // marks the ray was not excluded from by hull or clip
    int mark = -1;      // with SharedMarks: the mark hit (its index there)
};

// Scratch space reused from ray to ray (nothing allocated per ray once grown).
struct PixelScratch {
    ClusterSystem sys;
    // sys's owner while one ray is solved (the marks of one patch, halves of
    // a bisection, share the ray's forms); reset by solve_pixel, since
    // others write sys too.
    FormsKey sys_of;
    std::vector<RayPatchHit> hits;
    std::vector<std::pair<double, int>> order;
    std::vector<std::pair<ParamBox, int>> boxes; // boxes still to solve, with their depth
};

// Step 6 with remark 1: the nearest intersection of the ray through (a, b)
// with the marked patches, nearest marks first; marks beyond a found hit are
// dropped (section 5, remark 2 after Theorem 10).
PixelHit solve_pixel(const ProjectedScene& ps, double a, double b, std::span<const Mark> marks,
                     PixelScratch& scratch, RenderStats& st);
// The same on a small sub-screen's shared marks: each is compared with the
// ray by hull, then solved as the comment at the top says.
PixelHit solve_pixel(const ProjectedScene& ps, double a, double b, SharedMarks& shared,
                     PixelScratch& scratch, RenderStats& st);

} // namespace seamless
