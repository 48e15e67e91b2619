// SPDX-License-Identifier: MIT
// INTRACY step 6 (single_pixels.h).
#include <seamless/render/pixels/single_pixels.h>

#include <seamless/render/pixels/pixel_lights.h>
#include <seamless/render/pixels/pixel_shade.h>
#include <seamless/render/scene/step_clock.h>

namespace seamless {

void SinglePixels::paint_pixel(const SubScreen& B, const Mark* marks, size_t n,
                               PixelScratch& scratch, RenderStats& st) {
    paint_hit(B.x0, B.y0, B.cause,
              solve_pixel(ps_, ps_.frame.screen_a(B.x0 + 0.5), ps_.frame.screen_b(B.y0 + 0.5),
                          {marks, n}, scratch, st),
              st);
}

void SinglePixels::paint_subscreen(const SubScreen& B, MarkStack& stack, PixelScratch& scratch,
                                   RenderStats& st) {
    const StepClock clock(st.single_pixel_seconds);
    shared_.reset(ps_, stack.coefs, &stack.marks[B.offset], B.count,
                  screen_a(ps_.frame, B.x0, B.x1), screen_b(ps_.frame, B.y0, B.y1), B.family);
    // All of B's rays first, then their shadows: the hits on one patch
    // share one certificate per light (pixel_lights.h).
    hits_.clear();
    for (int y = B.y0; y <= B.y1; ++y)
        for (int x = B.x0; x <= B.x1; ++x)
            hits_.push_back(
                solve(ps_.frame.screen_a(x + 0.5), ps_.frame.screen_b(y + 0.5), scratch, st));
    if (ts_) share_lights();
    size_t i = 0;
    for (int y = B.y0; y <= B.y1; ++y)
        for (int x = B.x0; x <= B.x1; ++x, ++i) {
            const Shaded& p = hits_[i];
            if (p.hit.candidates == 0) { // every mark certainly missed before any solve
                canvas_.background({x, y, x, y}, st);
                continue;
            }
            paint_hit(x, y, B.cause, p.hit, st, &p);
        }
    // Each pixel is a one-pixel sub-screen: counted once for all (a map lookup each).
    st.subscreens_by_size[1] += static_cast<long long>(hits_.size());
}

// The ray through (a, b) on the shared marks, with the point and normal at its hit.
SinglePixels::Shaded SinglePixels::solve(double a, double b, PixelScratch& scratch,
                                         RenderStats& st) {
    Shaded p;
    p.hit = solve_pixel(ps_, a, b, shared_, scratch, st);
    if (p.hit.patch < 0) return p;
    const BezierPatch& patch = ps_.patches[p.hit.patch].patch;
    // A hit by certified Newton is shaded at Newton's point, from the
    // evaluation its certificate made there (the mark's next start). Others
    // are evaluated at the hit, the next Newton run's first step on that mark.
    const SurfacePoint* at = p.hit.mark >= 0 ? shared_.at_start(p.hit.mark) : nullptr;
    if (at) {
        const double* st0 = shared_.start(p.hit.mark);
        surface_frame(patch, st0[0], st0[1], *at, p.P, p.N);
    } else {
        SurfacePoint sp;
        surface_frame(patch, p.hit.s, p.hit.t, p.P, p.N, &sp);
        if (p.hit.mark >= 0) shared_.evaluated(p.hit.mark, p.hit.s, p.hit.t, sp);
    }
    return p;
}

// Per patch hit by four or more of hits_ (from two on cost more than it
// saved): the lights certainly reaching the hull of their points (world
// coordinates), into lit_ (pixel_lights.h).
void SinglePixels::share_lights() {
    const size_t nl = scene_.lights.size();
    lit_.assign(hits_.size() * nl, 0);
    light_hints_.resize(nl, -1);
    for (size_t i = 0; i < hits_.size(); ++i) {
        const int patch = hits_[i].hit.patch;
        if (patch < 0 || hits_[i].group >= 0) continue;
        IVec<3> Pw = IVec<3>::empty();
        int n = 0;
        for (size_t j = i; j < hits_.size(); ++j) {
            if (hits_[j].hit.patch != patch) continue;
            hits_[j].group = static_cast<int>(i);
            const Vec3 w = ps_.frame.to_world(hits_[j].P);
            for (int c = 0; c < 3; ++c) Pw[c] = hull(Pw[c], Interval(w[c]));
            ++n;
        }
        if (n >= 4)
            lights_reaching_box(scene_, *ts_, Pw, patch, &lit_[i * nl], light_hints_.data());
    }
}

// shaded: h's point and normal, and its lights' certificates, when
// paint_subscreen has them.
void SinglePixels::paint_hit(int x, int y, int cause, const PixelHit& h, RenderStats& st,
                             const Shaded* shaded) {
    ++st.single_pixels;
    ++st.single_pixels_by_cause[cause];
    if (h.patch < 0) {
        canvas_.background({x, y, x, y}, st);
    } else {
        const char* lit = shaded && shaded->group >= 0 && !lit_.empty()
                              ? &lit_[shaded->group * scene_.lights.size()]
                              : nullptr;
        const auto I = shaded ? shade_at(ps_, scene_, ts_, h.patch, shaded->P, shaded->N, lit)
                              : shade_hit(ps_, scene_, ts_, h);
        canvas_.intensity(x, y, I);
    }
    if (!shaded) ++st.subscreens_by_size[1]; // paint_subscreen counts its pixels at once
}

} // namespace seamless
