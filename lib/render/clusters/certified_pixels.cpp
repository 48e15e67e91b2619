// SPDX-License-Identifier: MIT
// The pixels of a certified cluster (certified_pixels.h).
#include <seamless/render/clusters/certified_pixels.h>

#include <seamless/render/pixels/pixel_lights.h>
#include <seamless/render/pixels/pixel_shade.h>
#include <seamless/render/scene/step_clock.h>
#include <seamless/render/shading/shading.h>

#include <algorithm>
#include <utility>

namespace seamless {

void CertifiedPixels::paint(const PixelRect& B, const ClusterAttemptResult& r, const Mark* marks,
                            size_t n, PixelScratch& scratch, RenderStats& st) {
    const StepClock clock(st.certified_pixel_seconds);
    const ProjectedPatch& pp = ps_.patches[r.patch];
    const size_t nl = scene_.lights.size();
    lit_.resize(nl);
    hints_.resize(nl, -1);
    // Where Newton starts: the last hit (the previous pixel, or the row's
    // first above at a row's start), with the patch evaluated there.
    NewtonRun slots[3];
    Starts runs{&slots[0], &slots[1], &slots[2]};
    *runs.last = {r.box.s.mid(), r.box.t.mid(), evaluate(pp.patch, r.box.s.mid(), r.box.t.mid())};
    for (int ty = B.y0; ty <= B.y1; ty += kTileHeight)
        for (int tx = B.x0; tx <= B.x1; tx += kTileWidth) {
            const PixelRect tile{tx, ty, std::min(B.x1, tx + kTileWidth - 1),
                                 std::min(B.y1, ty + kTileHeight - 1)};
            // The tile's rays first, then their shading: the hits on the
            // certified patch share one certificate per light (pixel_lights.h).
            IVec<3> Pw = IVec<3>::empty();
            const int on_patch = solve_tile(tile, r, {marks, n}, runs, Pw, scratch, st);
            const bool shared = ts_ && on_patch >= 4;
            if (shared) lights_reaching_box(scene_, *ts_, Pw, r.patch, lit_.data(), hints_.data());
            shade_tile(tile, r.patch, shared, st);
        }
    const long long area = B.count();
    st.certified_pixels_by_cause[r.cause] += area;
    st.subscreens_by_size[1] += area;
}

// The rays of a tile into hits_, row by row; Pw: the hull of the hits on the
// certified patch (world coordinates, with secondary rays in play). Returns
// how many hit that patch.
int CertifiedPixels::solve_tile(const PixelRect& tile, const ClusterAttemptResult& r,
                                const Marks& marks, Starts& runs, IVec<3>& Pw,
                                PixelScratch& scratch, RenderStats& st) {
    const ProjectedPatch& pp = ps_.patches[r.patch];
    const Mark only{r.patch, r.box, {}};
    // Three slots, the last hit, the row's first and the next, swapped by
    // pointer rather than copied per pixel.
    NewtonRun *last = runs.last, *row = runs.row, *next = runs.next;
    hits_.clear();
    int on_patch = 0;
    *row = *last;
    for (int y = tile.y0; y <= tile.y1; ++y) {
        *last = *row;
        int last_x = -1; // the pixel of this row where `last` was set
        const double b = ps_.frame.screen_b(y + 0.5);
        for (int x = tile.x0; x <= tile.x1; ++x) {
            const double a = ps_.frame.screen_a(x + 0.5);
            ++st.primary_rays;
            Shaded& p = hits_.emplace_back();
            const bool along = x > tile.x0 && last_x == x - 1;
            if (newton_in_box(pp.patch, a, b, r.box, *last, along, *next)) {
                p.hit = PixelHit{r.patch, next->s, next->t, 0};
            } else {
                *next = {}; // a fallback's hit: no correction, k unknown
                ++st.certified_pixel_fallbacks;
                p.hit = solve_pixel(ps_, a, b, {&only, 1}, scratch, st);
                if (p.hit.patch < 0)
                    p.hit = solve_pixel(ps_, a, b, {marks.marks, marks.n}, scratch, st);
            }
            if (p.hit.patch < 0) continue;
            surface_frame(ps_.patches[p.hit.patch].patch, p.hit.s, p.hit.t, p.P, p.N, &next->at);
            if (p.hit.patch != r.patch) continue;
            // The next pixel's Newton starts here.
            next->s = p.hit.s;
            next->t = p.hit.t;
            std::swap(last, next);
            last_x = x;
            if (x == tile.x0) *row = *last;
            if (ts_) {
                const Vec3 w = ps_.frame.to_world(p.P);
                for (int c = 0; c < 3; ++c) Pw[c] = hull(Pw[c], Interval(w[c]));
            }
            ++on_patch;
        }
    }
    runs = {last, row, next};
    return on_patch;
}

// SHADE at the tile's hits (hits_), the lights in lit_ taken as reaching the
// certified patch's hits when `shared`.
void CertifiedPixels::shade_tile(const PixelRect& tile, int patch, bool shared, RenderStats& st) {
    size_t i = 0;
    for (int y = tile.y0; y <= tile.y1; ++y)
        for (int x = tile.x0; x <= tile.x1; ++x, ++i) {
            const Shaded& p = hits_[i];
            std::array<double, 3> I;
            if (p.hit.patch < 0) { // every mark certainly missed (step 6)
                for (int c = 0; c < 3; ++c) I[c] = ps_.lighting.background[c];
                ++st.background_pixels;
            } else {
                I = shade_at(ps_, scene_, ts_, p.hit.patch, p.P, p.N,
                             shared && p.hit.patch == patch ? lit_.data() : nullptr);
                image_.surface_at(x, y) = 1;
            }
            for (int c = 0; c < 3; ++c)
                image_.at(x, y, c) = static_cast<std::uint16_t>(quantise(I[c], levels_));
        }
}

} // namespace seamless
