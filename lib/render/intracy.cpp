// SPDX-License-Identifier: MIT
// INTRACY (paper section 7): the sub-screen loop. Single pixels and corner rays
// are solved in pixel_solve.h, a certified cluster is shaded by cluster_shade.h
// (SHADE with shadows and secondary clusters; optics.h for their directions).
//
// The screen is prepartitioned into 8 x 8 parts (remark 4), each handled with
// its own stack of sub-screens B and run in parallel. For each B:
//  step 3: every marked patch is compared with B by hull (remark 1 of Prop. 11
//          in its primary-ray form: the hull of its projected control points),
//          then its (s, t) intervals are narrowed (Theorem 10's question, by
//          Bezier clipping of the subpatch the mark carries from its parent,
//          mark.h), separated at the midpoints where a silhouette is possible
//          (remark 3), bisected where they stay wide (covering method); a patch
//          whose intervals become empty is unmarked;
//  step 5: B shrinks to the hull of the projections of the marked patches; the
//          rest of B is background, certainly;
//  step 6: a one-pixel B is solved on every marked patch, nearest first
//          (remark 1), by certified Newton with the covering method as the
//          fallback (pixel_solve.h); so is every pixel of a B of at most
//          RenderOptions::pixel_subscreen pixels, without a cluster attempt;
//  steps 7-9: otherwise the cluster attempt (cluster_attempt.h): a nearest
//          patch certified to cover B (Theorem 6 iii for every ray of B at
//          once), SHADE's intensity enclosure, and B painted where it holds at
//          most two levels (bilinear form of the corner intensities, remark 2);
//          where step 7 holds but SHADE (a light) or step 9 (span) fails, a B
//          up to a size is painted one ray per pixel from that certificate
//          (certified_pixels.h) instead of split;
//  step 10: otherwise B is split into four (remark 3), or two, and pushed;
//          children of a B whose step 9 failed by far skip steps 7-9.
// Background is never painted where a patch is hit.
#include <seamless/render/clusters/certified_pixels.h>
#include <seamless/render/clusters/cluster_attempt.h>
#include <seamless/render/pixels/pixel_lights.h>
#include <seamless/render/pixels/pixel_shade.h>
#include <seamless/render/pixels/pixel_solve.h>
#include <seamless/render/render.h>
#include <seamless/render/scene/projection.h>
#include <seamless/render/scene/render_loop.h>
#include <seamless/render/scene/step_clock.h>
#include <seamless/render/shading/shading.h>
#include <seamless/render/subscreen/mark.h>
#include <seamless/render/subscreen/primary_cluster.h>
#include <seamless/render/subscreen/shared_marks.h>
#include <seamless/render/tray/ray_cluster.h>
#include <seamless/render/tray/trace.h>

#include <seamless/interval/hansen_sengupta.h>
#include <seamless/model/model.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <memory>
#include <mutex>
#include <optional>

namespace seamless {
namespace {

struct SubScreen {
    int x0, y0, x1, y1;    // inclusive pixel range
    size_t offset, count;  // its marks in the arena
    size_t coef_end;       // end of its marks' subpatches in the coefficient arena
    bool attempt;          // try step 7 (false: its parent's intensity was far too wide)
    int cause;             // why its nearest attempting ancestor split (RenderStats::SplitCause)
    long long family = -1; // the same for the children of one parent (SharedMarks::reset)
};

// A pixel of a small B (paint_pixels): its hit, the point and normal there
// (camera coordinates), and the first pixel of B hitting the same patch.
struct PixelShade {
    PixelHit hit;
    Vec3 P, N;
    int group = -1;
};

// Every patch's whole-patch mark and its subpatch (whole_patch_mark, in patch
// order), made once per render: each part starts from a copy (teapot 640x480:
// 64 parts x 36 patches made them 2,304 times, 6.2 M instructions).
struct WholeMarks {
    std::vector<Mark> marks;
    SubpatchArena coefs;

    explicit WholeMarks(const ProjectedScene& ps) {
        marks.reserve(ps.patches.size());
        for (size_t k = 0; k < ps.patches.size(); ++k) {
            const ProjectedPatch& pp = ps.patches[k];
            marks.push_back(
                whole_patch_mark(static_cast<int>(k), pp.patch, pp.shape, pp.hull, coefs));
        }
    }
};

class PartRenderer {
  public:
    PartRenderer(const ProjectedScene& ps, const WholeMarks& whole, const Scene& scene,
                 const TriangleScene* ts, const std::vector<int>* neighbours,
                 const RenderOptions& opt, Image& image, int levels)
        : ps_(ps), whole_(whole), scene_(scene), ts_(ts), opt_(opt), image_(image), levels_(levels),
          attempt_(ps, scene, ts, neighbours, opt, image, levels),
          certified_(ps, scene, ts, image, levels) {
        const Vec3 bg = ps.lighting.background;
        for (int c = 0; c < 3; ++c) bg_[c] = static_cast<std::uint16_t>(quantise(bg[c], levels));
    }

    void run(int x0, int y0, int x1, int y1, RenderStats& st) {
        arena_.assign(whole_.marks.begin(), whole_.marks.end());
        coefs_.assign(whole_.coefs.begin(), whole_.coefs.end());
        stack_.clear();
        stack_.push_back(
            {x0, y0, x1, y1, 0, arena_.size(), coefs_.size(), true, RenderStats::none});
        const long long enclosures0 = range_enclosure_count();
        const PartCpuScale cpu;
        while (!stack_.empty()) {
            SubScreen B = stack_.back();
            stack_.pop_back();
            arena_.resize(B.offset + B.count);
            coefs_.resize(B.coef_end);
            ++st.subscreens;
            step(B, st);
        }
        st.range_enclosures += range_enclosure_count() - enclosures0;
        st.shade_seconds -= st.secondary_seconds; // reported apart
        const double f = cpu.factor();
        for (double* x :
             {&st.narrow_seconds, &st.certify_seconds, &st.shade_seconds, &st.secondary_seconds,
              &st.single_pixel_seconds, &st.certified_pixel_seconds})
            *x *= f;
    }

  private:
    Interval screen_a(int x0, int x1) const {
        return {ps_.frame.screen_a(x0 + 0.5), ps_.frame.screen_a(x1 + 0.5)};
    }
    Interval screen_b(int y0, int y1) const {
        return {ps_.frame.screen_b(y0 + 0.5), ps_.frame.screen_b(y1 + 0.5)};
    }

    void paint_background(int x0, int y0, int x1, int y1, RenderStats& st) {
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x)
                for (int c = 0; c < 3; ++c) image_.at(x, y, c) = bg_[c];
        st.background_pixels += static_cast<long long>(x1 - x0 + 1) * (y1 - y0 + 1);
    }
    static long long pixel_count(const SubScreen& B) {
        return static_cast<long long>(B.x1 - B.x0 + 1) * (B.y1 - B.y0 + 1);
    }
    void count(const SubScreen& B, RenderStats& st) { ++st.subscreens_by_size[pixel_count(B)]; }

    void step(SubScreen B, RenderStats& st) {
        const bool thin = B.x0 == B.x1 && B.y0 == B.y1;
        if (!thin && pixel_count(B) <= opt_.pixel_subscreen) {
            paint_pixels(B, st);
            return;
        }
        const Interval a = screen_a(B.x0, B.x1), b = screen_b(B.y0, B.y1);
        // Step 3: hull comparison and Theorem 10 for every marked patch.
        const size_t first = arena_.size();
        const double pitch_a = 2.0 * ps_.frame.tan_half * ps_.frame.aspect / ps_.frame.width;
        const double pitch_b = 2.0 * ps_.frame.tan_half / ps_.frame.height;
        std::optional<StepClock> narrowing;
        if (!thin) narrowing.emplace(st.narrow_seconds);
        for (size_t k = B.offset; k < B.offset + B.count; ++k) {
            // Covering method (section 5, remark 2 after Theorem 10): where Theorem 10
            // cannot narrow a box (near a silhouette) and the box still projects far
            // beyond B, it is bisected and both halves go on.
            work_.clear();
            work_.push_back(arena_[k]);
            int budget = kMaxBisections;
            while (!work_.empty()) {
                Mark m = work_.back();
                work_.pop_back();
                // Hull comparison with the enclosures the mark brought from its parent.
                if (!may_meet(m, a, b)) continue;
                if (thin) {
                    arena_.push_back(m);
                    continue;
                }
                const SubpatchShape sh = ps_.patches[m.patch].shape;
                ++st.marks_narrowed;
                IMat<2> A;
                if (!narrow_mark(coefs_, sh, a, b, m, &A)) continue;
                update_enclosures(coefs_, sh, m);
                const IVec3& Q = m.hull;
                const Interval pa = m.pa.is_finite() ? m.pa : Q[0] / Q[2];
                const Interval pb = m.pb.is_finite() ? m.pb : Q[1] / Q[2];
                const bool wide = !(Q[2].lo() > 0) || pa.width() > 2 * (a.width() + pitch_a) ||
                                  pb.width() > 2 * (b.width() + pitch_b);
                if (wide && budget > 0 && std::max(m.box.s.width(), m.box.t.width()) > 1e-9) {
                    --budget;
                    ++st.mark_bisections;
                    Mark half[2];
                    bisect_mark(coefs_, sh, m, m.box.s.width() >= m.box.t.width() ? 0 : 1, half);
                    work_.push_back(half[1]);
                    work_.push_back(half[0]);
                    continue;
                }
                // Remark 3: where a silhouette is possible the patch is separated. In
                // the projected problem the silhouette is where the Jacobian of G
                // (the projected normal's z component) vanishes; its entries are the
                // clipping's last derivative ranges, over subpatches holding m.box.
                const Interval J = A(0, 0) * A(1, 1) - A(0, 1) * A(1, 0);
                Mark parts[2];
                const int n =
                    J.contains(0.0) ? separate_mark(coefs_, sh, a, b, m, parts) : (parts[0] = m, 1);
                for (int i = 0; i < n; ++i) arena_.push_back(parts[i]);
            }
        }
        narrowing.reset();
        const size_t nmarks = arena_.size() - first;
        if (nmarks == 0) { // step 4: nothing marked
            paint_background(B.x0, B.y0, B.x1, B.y1, st);
            count(B, st);
            return;
        }
        if (thin) {
            const StepClock clock(st.single_pixel_seconds);
            paint_single_pixel(B, first, nmarks, st);
            return;
        }
        // Step 5: B shrinks to the hull of the projections of the marked patches.
        if (improve(B, first, nmarks, st)) return;
        // Steps 7 to 9: the cluster attempt (cluster_attempt.h).
        int levels_over = 0;
        int cause = B.cause;
        if (B.attempt) {
            const ClusterAttemptResult r = attempt_.try_paint(
                {B.x0, B.y0, B.x1, B.y1}, &arena_[first], nmarks, coefs_, pixel_, st);
            if (r.cause < 0) return;
            if (r.proven && fill(r, pixel_count(B))) {
                ++st.attempts_failed[r.cause];
                certified_.paint({B.x0, B.y0, B.x1, B.y1}, r, &arena_[first], nmarks, pixel_, st);
                return;
            }
            cause = r.cause;
            levels_over = r.levels_over;
            ++st.attempts_failed[cause];
        }
        // Step 9 failed by far: the children's enclosures (about half as wide)
        // would fail too; they split at once and their children try again.
        const bool kids_attempt = children_attempt(levels_over);
        // Step 10: split into four while possible (remark 3), else two.
        const int w = B.x1 - B.x0 + 1, h = B.y1 - B.y0 + 1;
        // Children that would all go to paint_pixels (none a single pixel):
        // B is painted pixel by pixel at once, its marks shared by all of its
        // pixels (one Jacobian per mark over B, each bisection once, Newton
        // from the last hit across the children's borders). Teapot 640x480 x
        // 16: paint_pixels 536 -> 501 M instructions, PNG byte-identical.
        if (w > 1 && h > 1 && (w >= 4 || h >= 4) &&
            static_cast<long long>(w - w / 2) * (h - h / 2) <= opt_.pixel_subscreen) {
            SubScreen P = B;
            P.offset = first;
            P.count = nmarks;
            P.coef_end = coefs_.size();
            P.cause = cause;
            P.family = families_++; // its own marks, not its siblings'
            paint_pixels(P, st);
            return;
        }
        const int xm = B.x0 + w / 2 - 1, ym = B.y0 + h / 2 - 1;
        SubScreen kids[4];
        int nk = 0;
        if (w > 1 && h > 1) {
            kids[nk++] = {B.x0, B.y0, xm, ym, 0, 0, 0, true, cause};
            kids[nk++] = {xm + 1, B.y0, B.x1, ym, 0, 0, 0, true, cause};
            kids[nk++] = {B.x0, ym + 1, xm, B.y1, 0, 0, 0, true, cause};
            kids[nk++] = {xm + 1, ym + 1, B.x1, B.y1, 0, 0, 0, true, cause};
        } else if (w > 1) {
            kids[nk++] = {B.x0, B.y0, xm, B.y1, 0, 0, 0, true, cause};
            kids[nk++] = {xm + 1, B.y0, B.x1, B.y1, 0, 0, 0, true, cause};
        } else {
            kids[nk++] = {B.x0, B.y0, B.x1, ym, 0, 0, 0, true, cause};
            kids[nk++] = {B.x0, ym + 1, B.x1, B.y1, 0, 0, 0, true, cause};
        }
        // Each child gets the marks of B (already at the top of the arena for
        // the first; copies for the others). Pushed in reverse so the first is next.
        for (int i = nk - 1; i >= 0; --i) {
            kids[i].offset = first;
            kids[i].count = nmarks;
            kids[i].coef_end = coefs_.size();
            kids[i].attempt = kids_attempt;
            kids[i].cause = cause;
            kids[i].family = families_;
        }
        ++families_;
        // All children share one mark list: a child's processing truncates the
        // arena to offset+count before appending, so the list survives for the next.
        for (int i = nk - 1; i >= 0; --i) stack_.push_back(kids[i]);
    }

    // Where step 7 holds for B but SHADE (light) or step 9 (span) failed:
    // paint B from the certificate (certified_pixels.h) rather than split it,
    // up to kFillLight or kFillSpan pixels; a B whose step 9 failed by far
    // (its children would split at once) at any size. Larger B split: their
    // children may pass as clusters (sizes chosen by callgrind counts on the
    // teapot and scenes 2, 3; bench/render/render_assessment.md, eighth round).
    bool fill(const ClusterAttemptResult& r, long long area) const {
        if (!opt_.certified_pixels) return false;
        if (r.cause == RenderStats::light) return area <= kFillLight;
        return area <= kFillSpan || !children_attempt(r.levels_over);
    }
    bool children_attempt(int levels_over) const {
        return levels_over <= 2 * ((opt_.dither ? 1 : 0) + 1);
    }

    // A small B is solved pixel by pixel from its marks (those of its parent),
    // without a cluster attempt: a few certified Newton solves cost less than
    // narrowing, certificate and SHADE for a cluster of a handful of pixels.
    // The pixels share the marks' Jacobians, Newton's starting points and the
    // bisections of marks a silhouette crosses (SharedMarks of shared_marks.h,
    // appended to coefs_ past B.coef_end).
    void paint_pixels(const SubScreen& B, RenderStats& st) {
        const StepClock clock(st.single_pixel_seconds);
        shared_.reset(ps_, coefs_, &arena_[B.offset], B.count, screen_a(B.x0, B.x1),
                      screen_b(B.y0, B.y1), B.family);
        // All of B's rays first, then their shadows: the hits on one patch
        // share one certificate per light (pixel_lights.h).
        hits_.clear();
        for (int y = B.y0; y <= B.y1; ++y)
            for (int x = B.x0; x <= B.x1; ++x) {
                PixelShade p;
                p.hit = solve_pixel(ps_, ps_.frame.screen_a(x + 0.5), ps_.frame.screen_b(y + 0.5),
                                    nullptr, 0, pixel_, st, &shared_);
                if (p.hit.patch >= 0) {
                    const BezierPatch& patch = ps_.patches[p.hit.patch].patch;
                    // A hit by certified Newton is shaded at Newton's point,
                    // from the evaluation its certificate made there (the
                    // mark's next start; teapot 640x480 x 16: render_intracy
                    // 921.95 -> 909.70 M instructions). Others are evaluated at
                    // the hit, the next Newton run's first step on that mark.
                    const SurfacePoint* at =
                        p.hit.mark >= 0 ? shared_.at_start(p.hit.mark) : nullptr;
                    if (at) {
                        const double* st0 = shared_.start(p.hit.mark);
                        surface_frame(patch, st0[0], st0[1], *at, p.P, p.N);
                    } else {
                        SurfacePoint sp;
                        surface_frame(patch, p.hit.s, p.hit.t, p.P, p.N, &sp);
                        if (p.hit.mark >= 0) shared_.evaluated(p.hit.mark, p.hit.s, p.hit.t, sp);
                    }
                }
                hits_.push_back(p);
            }
        if (ts_) share_lights();
        size_t i = 0;
        for (int y = B.y0; y <= B.y1; ++y)
            for (int x = B.x0; x <= B.x1; ++x, ++i) {
                const SubScreen pixel{x, y, x, y, 0, 0, 0, true, B.cause};
                const PixelShade& p = hits_[i];
                if (p.hit.candidates == 0) { // every mark certainly missed before any solve
                    paint_background(x, y, x, y, st);
                    continue;
                }
                paint_hit(pixel, p.hit, st, &p);
            }
        // Each pixel is a one-pixel sub-screen: counted once for all (a map lookup each).
        st.subscreens_by_size[1] += static_cast<long long>(hits_.size());
    }

    // Per patch hit by four or more of hits_: the lights certainly reaching
    // the hull of their points (world coordinates), into lit_ (pixel_lights.h).
    // (From two on: 2 M instructions more on the teapot and on scene 3.)
    void share_lights() {
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
    // Step 6: a one-pixel B, solved by Hansen-Sengupta on its marked patches.
    void paint_single_pixel(const SubScreen& B, size_t first, size_t n, RenderStats& st) {
        paint_hit(B,
                  solve_pixel(ps_, ps_.frame.screen_a(B.x0 + 0.5), ps_.frame.screen_b(B.y0 + 0.5),
                              &arena_[first], n, pixel_, st),
                  st);
    }
    // shaded: h's point and normal, and its lights' certificates, when paint_pixels has them.
    void paint_hit(const SubScreen& B, const PixelHit& h, RenderStats& st,
                   const PixelShade* shaded = nullptr) {
        ++st.single_pixels;
        ++st.single_pixels_by_cause[B.cause];
        if (h.patch < 0) {
            paint_background(B.x0, B.y0, B.x0, B.y0, st);
        } else {
            const char* lit = shaded && shaded->group >= 0 && !lit_.empty()
                                  ? &lit_[shaded->group * scene_.lights.size()]
                                  : nullptr;
            const auto I = shaded ? shade_at(ps_, scene_, ts_, h.patch, shaded->P, shaded->N, lit)
                                  : shade_hit(ps_, scene_, ts_, h);
            for (int c = 0; c < 3; ++c)
                image_.at(B.x0, B.y0, c) = static_cast<std::uint16_t>(quantise(I[c], levels_));
            image_.surface_at(B.x0, B.y0) = 1;
        }
        if (!shaded) count(B, st); // paint_pixels counts its pixels at once
    }

    // Step 5. Returns true if B was finished (all background).
    bool improve(SubScreen& B, size_t first, size_t n, RenderStats& st) {
        Interval ha = Interval::empty(), hb = Interval::empty();
        for (size_t k = first; k < first + n; ++k) {
            const Mark& m = arena_[k];
            if (m.pa.is_finite() && m.pb.is_finite()) {
                ha = hull(ha, m.pa);
                hb = hull(hb, m.pb);
                continue;
            }
            const IVec3& P = m.hull;
            if (!(P[2].lo() > 0)) return false; // crosses the eye plane: no projection hull
            ha = hull(ha, P[0] / P[2]);
            hb = hull(hb, P[1] / P[2]);
        }
        int nx0 = B.x0, nx1 = B.x1, ny0 = B.y0, ny1 = B.y1;
        while (nx0 <= nx1 && ps_.frame.screen_a(nx0 + 0.5) < ha.lo()) ++nx0;
        while (nx1 >= nx0 && ps_.frame.screen_a(nx1 + 0.5) > ha.hi()) --nx1;
        while (ny0 <= ny1 && ps_.frame.screen_b(ny0 + 0.5) < hb.lo()) ++ny0;
        while (ny1 >= ny0 && ps_.frame.screen_b(ny1 + 0.5) > hb.hi()) --ny1;
        if (nx0 > nx1 || ny0 > ny1) {
            paint_background(B.x0, B.y0, B.x1, B.y1, st);
            count(B, st);
            return true;
        }
        if (nx0 == B.x0 && nx1 == B.x1 && ny0 == B.y0 && ny1 == B.y1) return false;
        // The strips of B outside the hull are background.
        if (ny0 > B.y0) paint_background(B.x0, B.y0, B.x1, ny0 - 1, st);
        if (ny1 < B.y1) paint_background(B.x0, ny1 + 1, B.x1, B.y1, st);
        if (nx0 > B.x0) paint_background(B.x0, ny0, nx0 - 1, ny1, st);
        if (nx1 < B.x1) paint_background(nx1 + 1, ny0, B.x1, ny1, st);
        B.x0 = nx0;
        B.x1 = nx1;
        B.y0 = ny0;
        B.y1 = ny1;
        if (B.x0 == B.x1 && B.y0 == B.y1) { // down to one pixel: solve it now
            const StepClock clock(st.single_pixel_seconds);
            paint_single_pixel(B, first, n, st);
            return true;
        }
        return false;
    }

    const ProjectedScene& ps_;
    const WholeMarks& whole_;
    const Scene& scene_;
    const TriangleScene* ts_; // null: no secondary rays in play
    const RenderOptions& opt_;
    Image& image_;
    int levels_;
    std::uint16_t bg_[3];
    static constexpr int kMaxBisections = 64; // per marked patch and sub-screen
    static constexpr long long kFillLight = 1280, kFillSpan = 320; // fill(): pixels of B
    std::vector<Mark> arena_, work_;
    SubpatchArena coefs_; // the marks' subpatches
    std::vector<SubScreen> stack_;
    PixelScratch pixel_;
    SharedMarks shared_;           // paint_pixels: the marks of a small B
    long long families_ = 0;       // SubScreen::family: ids given so far
    std::vector<PixelShade> hits_; // paint_pixels: B's hits, row by row
    std::vector<char> lit_;        // share_lights: per hits_ index (a group's first), per light
    std::vector<int> light_hints_; // share_lights: per light, the last triangle that may block it
    ClusterAttempt attempt_;       // steps 7 to 9
    CertifiedPixels certified_;    // B certified at step 7, failed at 8 or 9
};

} // namespace

Image render_intracy(const Scene& scene, const RenderOptions& opt, RenderStats& st) {
    const int W = opt.width > 0 ? opt.width : scene.camera.width;
    const int H = opt.height > 0 ? opt.height : scene.camera.height;
    const int L = opt.levels > 0 ? opt.levels : scene.levels;
    const auto t0 = std::chrono::steady_clock::now();
    // The model's Bezier patches (knot insertion), extracted once for the
    // triangle scene and step 1.
    const std::vector<BezierPatch> patches = bezier_patches(scene.model);
    // Secondary rays (SHADE steps 2-4) need the triangles and patch trees; a
    // scene without lit diffuse or specular surfaces and without mirrors or
    // glass needs none, and gets none.
    std::unique_ptr<TriangleScene> ts;
    std::vector<int> neighbours; // for shadows by a surface of triangles (ray_cluster.h)
    if (needs_secondary_rays(scene)) {
        ts = std::make_unique<TriangleScene>(build_triangle_scene(scene, patches, opt.threads));
        st.triangles = ts->tess.mesh.triangle_count();
        neighbours = triangle_neighbours(ts->tess.mesh.triangles);
        add_light_planes(scene, *ts);
    }
    // Step 1 after the triangle scene: its patch array and temporaries then
    // partly reuse memory the tessellation freed (teapot 640x480 x 16, 2
    // threads: 1,698 -> 1,658 page faults, task-clock 156.3 -> 154.6 ms,
    // medians of 11; step 1 first, overlapped with the triangle scene on a
    // thread of its own, gained nothing: both cores are busy there).
    const ProjectedScene ps = project_scene(scene, patches, W, H, opt.threads);
    st.precalc_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    st.patches = static_cast<long long>(ps.patches.size());
    Image image(W, H, L, Image::Unfilled{}); // each part clears its own pixels
    const WholeMarks whole(ps);

    // Remark 4: 8 x 8 congruent parts (fewer when the image is smaller).
    const int px = std::min(opt.prepartition, W), py = std::min(opt.prepartition, H);
    const int parts = px * py;
    std::vector<RenderStats> part_stats(parts);
    std::atomic<int> done{0};
    // A part takes a free renderer (made when none is free: at most one per
    // worker) and gives it back, so its scratch vectors keep their capacity
    // from part to part instead of growing again into fresh pages.
    std::mutex free_lock;
    std::vector<std::unique_ptr<PartRenderer>> free_renderers;
    auto work = [&](int p) {
        const int i = p % px, j = p / px;
        const int x0 = i * W / px, x1 = (i + 1) * W / px - 1;
        const int y0 = j * H / py, y1 = (j + 1) * H / py - 1;
        image.clear(x0, y0, x1, y1);
        std::unique_ptr<PartRenderer> r;
        {
            const std::lock_guard<std::mutex> hold(free_lock);
            if (!free_renderers.empty()) {
                r = std::move(free_renderers.back());
                free_renderers.pop_back();
            }
        }
        if (!r)
            r = std::make_unique<PartRenderer>(ps, whole, scene, ts.get(),
                                               ts ? &neighbours : nullptr, opt, image, L);
        r->run(x0, y0, x1, y1, part_stats[p]);
        {
            const std::lock_guard<std::mutex> hold(free_lock);
            free_renderers.push_back(std::move(r));
        }
        const int d = ++done;
        if (opt.progress) opt.progress(static_cast<double>(d) / parts);
    };
    for_each_item(parts, opt.threads, work);
    for (const RenderStats& s : part_stats) st.merge(s);
    return image;
}

} // namespace seamless
