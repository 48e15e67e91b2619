// SPDX-License-Identifier: MIT
// INTRACY (paper section 7): the sub-screen loop, each step in the room that
// holds it. The screen is prepartitioned into 8 x 8 parts (remark 4), each
// handled with its own stack of sub-screens B (subscreen.h) and run in
// parallel. For each B:
//  step 3: its marked patches compared with B by hull and narrowed by
//          Theorem 10, separated where a silhouette is possible (narrowing.h);
//  step 4: nothing marked: B is background;
//  step 5: B shrinks to the hull of the projections of the marked patches; the
//          rest of B is background, certainly (shrink.h);
//  step 6: a one-pixel B is solved on every marked patch, nearest first, and
//          shaded at its hit; so is every pixel of a B of at most
//          RenderOptions::pixel_subscreen pixels, without a cluster attempt
//          (single_pixels.h);
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
#include <seamless/render/pixels/pixel_solve.h>
#include <seamless/render/pixels/single_pixels.h>
#include <seamless/render/render.h>
#include <seamless/render/scene/canvas.h>
#include <seamless/render/scene/projection.h>
#include <seamless/render/scene/render_loop.h>
#include <seamless/render/scene/step_clock.h>
#include <seamless/render/subscreen/mark.h>
#include <seamless/render/subscreen/narrowing.h>
#include <seamless/render/subscreen/shrink.h>
#include <seamless/render/subscreen/subscreen.h>
#include <seamless/render/tray/blocking_surface.h>
#include <seamless/render/tray/trace.h>

#include <seamless/model/model.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <memory>
#include <mutex>

namespace seamless {
namespace {

// What every part renders from (step 1's projected scene and whole-patch
// marks, the triangles for secondary rays when in play) and into.
struct PartContext {
    const ProjectedScene& ps;
    const MarkStack& whole;
    const Scene& scene;
    const TriangleScene* ts;            // null: no secondary rays in play
    const std::vector<int>* neighbours; // ts's triangle_neighbours, with ts
    const RenderOptions& opt;
    Image& image;
    int levels;
};

// One part of the screen (remark 4) with its own stack of sub-screens.
class PartRenderer {
  public:
    explicit PartRenderer(const PartContext& c)
        : whole_(c.whole), opt_(c.opt), canvas_(c.image, c.levels, c.ps.lighting.background),
          narrowing_(c.ps), pixels_(c.ps, c.scene, c.ts, canvas_),
          attempt_(c.ps, c.scene, c.ts, c.neighbours, c.opt, c.image, c.levels),
          certified_(c.ps, c.scene, c.ts, c.image, c.levels), frame_(c.ps.frame) {}

    void run(int x0, int y0, int x1, int y1, RenderStats& st) {
        marks_.marks.assign(whole_.marks.begin(), whole_.marks.end());
        marks_.coefs.assign(whole_.coefs.begin(), whole_.coefs.end());
        stack_.clear();
        stack_.push_back(
            {x0, y0, x1, y1, 0, marks_.marks.size(), marks_.coefs.size(), true, RenderStats::none});
        const long long enclosures0 = range_enclosure_count();
        const PartCpuScale cpu;
        while (!stack_.empty()) {
            SubScreen B = stack_.back();
            stack_.pop_back();
            marks_.marks.resize(B.offset + B.count);
            marks_.coefs.resize(B.coef_end);
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
    void count(const SubScreen& B, RenderStats& st) { ++st.subscreens_by_size[B.pixel_count()]; }

    // Section 7's steps for one sub-screen B, in the paper's order.
    void step(SubScreen B, RenderStats& st) {
        if (!B.thin() && B.pixel_count() <= opt_.pixel_subscreen) {
            pixels_.paint_subscreen(B, marks_, pixel_, st); // step 6, pixel by pixel
            return;
        }
        // Step 3: hull comparison and Theorem 10 for every marked patch.
        const size_t first = marks_.marks.size();
        narrowing_.narrow(marks_, B, st);
        const size_t nmarks = marks_.marks.size() - first;
        if (nmarks == 0) { // step 4: nothing marked
            canvas_.background(B.rect(), st);
            count(B, st);
            return;
        }
        if (B.thin()) { // step 6
            const StepClock clock(st.single_pixel_seconds);
            pixels_.paint_pixel(B, &marks_.marks[first], nmarks, pixel_, st);
            return;
        }
        if (shrink(B, first, nmarks, st)) return; // step 5
        // Steps 7 to 9: the cluster attempt (cluster_attempt.h).
        int levels_over = 0;
        int cause = B.cause;
        if (B.attempt) {
            const ClusterAttemptResult r = attempt_.try_paint(B.rect(), &marks_.marks[first],
                                                              nmarks, marks_.coefs, pixel_, st);
            if (r.cause < 0) return;
            if (r.proven && fill(r, B.pixel_count())) {
                ++st.attempts_failed[r.cause];
                certified_.paint(B.rect(), r, &marks_.marks[first], nmarks, pixel_, st);
                return;
            }
            cause = r.cause;
            levels_over = r.levels_over;
            ++st.attempts_failed[cause];
        }
        B.offset = first;
        B.count = nmarks;
        B.coef_end = marks_.coefs.size();
        B.cause = cause;
        split(B, levels_over, st); // step 10
    }

    // Step 5: B shrinks to the hull of the projections of its marks, the rest
    // of it painted background. Returns true if B was finished.
    bool shrink(SubScreen& B, size_t first, size_t n, RenderStats& st) {
        const PixelRect r = shrink_to_marks(frame_, B.rect(), &marks_.marks[first], n);
        if (r.empty()) {
            canvas_.background(B.rect(), st);
            count(B, st);
            return true;
        }
        if (r == B.rect()) return false;
        canvas_.background_around(B.rect(), r, st);
        B.x0 = r.x0;
        B.x1 = r.x1;
        B.y0 = r.y0;
        B.y1 = r.y1;
        if (B.thin()) { // down to one pixel: step 6 now
            const StepClock clock(st.single_pixel_seconds);
            pixels_.paint_pixel(B, &marks_.marks[first], n, pixel_, st);
            return true;
        }
        return false;
    }

    // Step 10 for B with its narrowed marks (B.offset, B.count) and the cause
    // of its split; levels_over: step 9's widest enclosure in levels.
    void split(const SubScreen& B, int levels_over, RenderStats& st) {
        // Children that would all go to paint_subscreen (none a single
        // pixel): B is painted pixel by pixel at once, its marks shared by
        // all of its pixels (one Jacobian per mark over B, each bisection
        // once, Newton from the last hit across the children's borders).
        const int w = B.x1 - B.x0 + 1, h = B.y1 - B.y0 + 1;
        if (w > 1 && h > 1 && (w >= 4 || h >= 4) &&
            static_cast<long long>(w - w / 2) * (h - h / 2) <= opt_.pixel_subscreen) {
            SubScreen P = B;
            P.family = families_++; // its own marks, not its siblings'
            pixels_.paint_subscreen(P, marks_, pixel_, st);
            return;
        }
        // Step 9 failed by far: the children's enclosures (about half as
        // wide) would fail too; they split at once and their children try again.
        const bool kids_attempt = children_attempt(levels_over);
        SubScreen kids[4];
        const int nk = split_subscreen(B, kids);
        // Each child gets the marks of B (already at the top of the arena for
        // the first; copies for the others). Pushed in reverse so the first is next.
        for (int i = nk - 1; i >= 0; --i) {
            kids[i].offset = B.offset;
            kids[i].count = B.count;
            kids[i].coef_end = B.coef_end;
            kids[i].attempt = kids_attempt;
            kids[i].cause = B.cause;
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
    // children may pass as clusters (the sizes took the fewest instructions
    // on the teapot and scenes 2 and 3: docs/results/render.md).
    bool fill(const ClusterAttemptResult& r, long long area) const {
        if (!opt_.certified_pixels) return false;
        if (r.cause == RenderStats::light) return area <= kFillLight;
        return area <= kFillSpan || !children_attempt(r.levels_over);
    }
    bool children_attempt(int levels_over) const {
        return levels_over <= 2 * ((opt_.dither ? 1 : 0) + 1);
    }

    static constexpr long long kFillLight = 1280, kFillSpan = 320; // fill(): pixels of B
    const MarkStack& whole_;
    const RenderOptions& opt_;
    Canvas canvas_;
    MarkStack marks_; // the marks of the sub-screens on stack_
    std::vector<SubScreen> stack_;
    long long families_ = 0; // SubScreen::family: ids given so far
    PixelScratch pixel_;
    MarkNarrowing narrowing_;   // step 3
    SinglePixels pixels_;       // step 6
    ClusterAttempt attempt_;    // steps 7 to 9
    CertifiedPixels certified_; // B certified at step 7, failed at 8 or 9
    const CameraFrame& frame_;
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
    std::vector<int> neighbours; // for shadows by a surface of triangles (blocking_surface.h)
    if (needs_secondary_rays(scene)) {
        ts = std::make_unique<TriangleScene>(build_triangle_scene(scene, patches, opt.threads));
        st.triangles = ts->tess.mesh.triangle_count();
        neighbours = triangle_neighbours(ts->tess.mesh.triangles);
        add_light_planes(scene, *ts);
    }
    // Step 1 after the triangle scene: its patch array and temporaries then
    // partly reuse memory the tessellation freed (fewer fresh pages).
    const ProjectedScene ps = project_scene(scene, patches, W, H, opt.threads);
    st.precalc_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    st.patches = static_cast<long long>(ps.patches.size());
    Image image(W, H, L, Image::Unfilled{}); // each part clears its own pixels
    const MarkStack whole = whole_marks(ps); // each part starts from a copy

    // Remark 4: 8 x 8 congruent parts (fewer when the image is smaller).
    const int px = std::min(opt.prepartition, W), py = std::min(opt.prepartition, H);
    const int parts = px * py;
    std::vector<RenderStats> part_stats(parts);
    const PartContext context{ps,  whole, scene, ts.get(), ts ? &neighbours : nullptr,
                              opt, image, L};
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
        if (!r) r = std::make_unique<PartRenderer>(context);
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
