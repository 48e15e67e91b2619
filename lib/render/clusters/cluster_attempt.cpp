// SPDX-License-Identifier: MIT
// The cluster attempt of INTRACY, steps 7 to 9 (cluster_attempt.h).
#include <seamless/render/clusters/cluster_attempt.h>

#include <seamless/render/clusters/second_order.h>
#include <seamless/render/pixels/pixel_shade.h>
#include <seamless/render/scene/step_clock.h>
#include <seamless/render/shading/shading.h>
#include <seamless/render/subscreen/subscreen.h>

#include <seamless/interval/hansen_sengupta.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace seamless {

namespace {

// Deterministic dither in [-0.5, 0.5) per pixel and channel (remark 2), so
// that sequential and parallel runs paint the same image.
double dither(int x, int y, int c) {
    std::uint64_t z = (static_cast<std::uint64_t>(x) << 40) ^
                      (static_cast<std::uint64_t>(y) << 16) ^ static_cast<std::uint64_t>(c) ^
                      0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * (1.0 / 9007199254740992.0) - 0.5;
}

// The normal of the best patch at the middle of its box, turned so that
// every ray of B crosses planes with that normal forward: a point X = Z d of
// a ray d = (a, b, 1) then has n . X = Z (n . d), growing with the depth Z.
// So where all points of one patch satisfy n . X < c and all of another
// n . X > c, the first is nearer on every ray of B that meets both (a plane
// separating them, with the eye on the first one's side along the rays).
// false when n . d may vanish on B.
bool separating_normal(const ProjectedPatch& pp, const ParamBox& box, Interval a, Interval b,
                       Vec3& n) {
    Vec3 P;
    surface_frame(pp.patch, box.s.mid(), box.t.mid(), P, n);
    const Interval nd = Interval(n.x) * a + Interval(n.y) * b + Interval(n.z);
    if (nd.hi() < 0) n = -1.0 * n;
    return nd.lo() > 0 || nd.hi() < 0;
}

bool share_corner(const BezierPatch& p, const BezierPatch& q) {
    for (int i = 0; i < 4; ++i) {
        const double scale = 1e-9 * (1 + norm(p.corner(i)));
        for (int j = 0; j < 4; ++j) {
            const Vec3 d = p.corner(i) - q.corner(j);
            if (std::abs(d.x) <= scale && std::abs(d.y) <= scale && std::abs(d.z) <= scale)
                return true;
        }
    }
    return false;
}

} // namespace

ClusterAttempt::ClusterAttempt(const ProjectedScene& ps, const Scene& scene,
                               const TriangleScene* ts, const std::vector<int>* neighbours,
                               const RenderOptions& opt, Image& image, int levels)
    : ps_(ps), scene_(scene), ts_(ts), dither_(opt.dither), image_(image), levels_(levels),
      shader_(ps, scene, ts, neighbours, levels, opt.dither),
      restricted_(4 * BezierPatch::kMaxOrder * BezierPatch::kMaxOrder) {}

// True when a corner ray of B certainly misses patch `patch`: it lies outside
// the screen enclosure of each of the patch's marks or (clip) one Bezier clip
// of the mark (clip_box of mark.h) leaves nothing. The marks hold every hit of
// B's rays on the patch (step 3), so that ray has no zero of G in [0,1]^2 and
// certify_cluster cannot prove one for every ray of B.
bool ClusterAttempt::corner_misses(const PixelRect& B, const MarkSpan& m, int patch,
                                   bool clip) const {
    const Mark* marks = m.marks;
    const size_t n = m.n;
    const SubpatchArena& coefs = m.coefs;
    const SubpatchShape sh = ps_.patches[patch].shape;
    const int cx[4] = {B.x0, B.x1, B.x0, B.x1}, cy[4] = {B.y0, B.y0, B.y1, B.y1};
    for (int k = 0; k < 4; ++k) {
        const double a = ps_.frame.screen_a(cx[k] + 0.5), b = ps_.frame.screen_b(cy[k] + 0.5);
        bool meets = false;
        for (size_t j = 0; j < n && !meets; ++j) {
            const Mark& mark = marks[j];
            if (mark.patch != patch) continue;
            if (mark.pa.is_finite() && mark.pb.is_finite() &&
                !(mark.pa.contains(a) && mark.pb.contains(b)))
                continue;
            ParamBox hit;
            meets = !clip || clip_box(coefs, sh, Interval(a), Interval(b), mark, hit);
        }
        if (!meets) return true;
    }
    return false;
}

// Why the certificate failed on B's marks (RenderStats::SplitCause).
int ClusterAttempt::certificate_cause(const Mark* marks, size_t n) const {
    const int p0 = marks[0].patch;
    bool one_surface = true, one_patch = true;
    for (size_t k = 0; k < n; ++k) {
        const int p = marks[k].patch;
        one_patch &= p == p0;
        one_surface &= ps_.patches[p].patch.surface == ps_.patches[p0].patch.surface;
    }
    if (one_patch) return RenderStats::one_patch;
    if (one_surface) return RenderStats::seam;
    // A seam between surfaces: every marked patch meets another at a corner.
    for (size_t k = 0; k < n; ++k) {
        bool meets = false;
        for (size_t j = 0; j < n && !meets; ++j)
            meets =
                marks[j].patch != marks[k].patch &&
                share_corner(ps_.patches[marks[k].patch].patch, ps_.patches[marks[j].patch].patch);
        if (!meets) return RenderStats::surfaces;
    }
    return RenderStats::surface_seam;
}

// The nearest patch by depth (q) intervals, or -1; box: the hull of its
// marks' boxes. The marks of one patch (halves of bisections, separated
// pieces) are taken together: their hull box holds every hit of that patch
// in B. The nearest patch must be q-separated from all other marks (a
// nearest q-connected set of one patch).
int ClusterAttempt::nearest_patch(const Mark* marks, size_t n, ParamBox& box) const {
    int best_patch = -1;
    double best_lo = std::numeric_limits<double>::infinity();
    for (size_t k = 0; k < n; ++k) {
        const Interval q = marks[k].hull[2];
        if (q.lo() < best_lo) {
            best_lo = q.lo();
            best_patch = marks[k].patch;
        }
    }
    if (best_patch < 0) return -1;
    box = ParamBox{Interval::empty(), Interval::empty()};
    for (size_t k = 0; k < n; ++k)
        if (marks[k].patch == best_patch) {
            box.s = hull(box.s, marks[k].box.s);
            box.t = hull(box.t, marks[k].box.t);
        }
    return best_patch;
}

// Step 7: c.patch certified for every ray of B in c.box (contracted there),
// with the enclosures of the hits (c.e, c.world). Returns -1 when it holds,
// else why not (RenderStats::SplitCause).
int ClusterAttempt::certify(const PixelRect& B, const MarkSpan& m, Certified& c, RenderStats& st) {
    const StepClock clock(st.certify_seconds);
    const ProjectedPatch& pp = ps_.patches[c.patch];
    const Interval a = screen_a(ps_.frame, B.x0, B.x1), b = screen_b(ps_.frame, B.y0, B.y1);
    // certify_cluster, with proofs of its failure before its first step
    // (a corner ray of B outside the screen enclosures of the patch's
    // marks) and between the first step and the rest (a corner ray that
    // a Bezier clip of the marks excludes): certify_cluster's cost is in
    // its failures that run every step.
    if (corner_misses(B, m, c.patch, false)) return certificate_cause(m.marks, m.n);
    cluster_system(pp.forms, a, b, sys_);
    IVec<2> x = cluster_start(c.box);
    ClusterCertificate cert = certify_steps(sys_, x, c.box, 1, &st.hs_steps);
    if (cert == ClusterCertificate::open && !corner_misses(B, m, c.patch, true))
        cert = certify_steps(sys_, x, c.box, kClusterCertifySteps - 1, &st.hs_steps);
    if (cert != ClusterCertificate::proven) return certificate_cause(m.marks, m.n);
    if (!enclose_hits(m, c)) return certificate_cause(m.marks, m.n);
    if (!(c.e.point[2].lo() > 0)) return certificate_cause(m.marks, m.n);
    return nearest_cause(m, c, a, b, st);
}

// The hits' enclosures from the marks' subpatches restricted to the
// certified box (every hit lies in it and in a mark): their control points'
// hulls in camera and in world coordinates, and the partial derivatives from
// the control points' differences: tighter than enclose_point's forms over
// the box, at a fraction of the cost. false when no mark meets the box.
bool ClusterAttempt::enclose_hits(const MarkSpan& m, Certified& c) {
    const ProjectedPatch& pp = ps_.patches[c.patch];
    PatchEnclosure& e = c.e;
    IVec3& point = e.point;
    point = c.world = e.ds = e.dt = IVec3::empty();
    bool derivatives = true;
    for (size_t k = 0; k < m.n; ++k) {
        ParamBox got;
        if (m.marks[k].patch != c.patch ||
            !restrict_mark(m.coefs, pp.shape, m.marks[k], c.box, restricted_.data(), got))
            continue;
        const IVec3 h = subpatch_hull(restricted_.data(), pp.shape);
        const IVec3 w = ts_ ? shader_.world_hull(restricted_.data(), pp.shape)
                            : IVec3{{Interval::entire(), Interval::entire(), Interval::entire()}};
        IVec3 ds, dt;
        derivatives =
            derivatives && subpatch_derivatives(restricted_.data(), pp.shape, got, h, ds, dt);
        for (int i = 0; i < 3; ++i) {
            point[i] = hull(point[i], h[i]);
            c.world[i] = hull(c.world[i], w[i]);
            e.ds[i] = hull(e.ds[i], ds[i]);
            e.dt[i] = hull(e.dt[i], dt[i]);
        }
    }
    if (point[2].is_empty()) return false;
    if (derivatives)
        e.normal = cross(e.ds, e.dt);
    else
        e = enclose(pp.forms, c.box, IVec3(point));
    return true;
}

// Nearest: every other mark q-separated from c's hits, or, where depths
// overlap, beyond a plane that c.patch's marks lie before. -1 when so, else
// RenderStats::not_nearest.
int ClusterAttempt::nearest_cause(const MarkSpan& m, const Certified& c, Interval a, Interval b,
                                  RenderStats& st) const {
    const ProjectedPatch& pp = ps_.patches[c.patch];
    const Mark* marks = m.marks;
    const Interval qbest = c.e.point[2];
    Interval best_range = Interval::empty();
    Vec3 normal{};
    for (size_t k = 0; k < m.n; ++k) {
        if (marks[k].patch == c.patch) continue;
        if (marks[k].hull[2].lo() > qbest.hi()) continue;
        if (best_range.is_empty()) {
            if (!separating_normal(pp, c.box, a, b, normal)) return RenderStats::not_nearest;
            for (size_t j = 0; j < m.n; ++j)
                if (marks[j].patch == c.patch)
                    best_range = hull(best_range, plane_range(m.coefs, pp.shape, marks[j], normal));
        }
        const Interval r =
            plane_range(m.coefs, ps_.patches[marks[k].patch].shape, marks[k], normal);
        if (!(r.lo() > best_range.hi())) return RenderStats::not_nearest;
    }
    st.nearest_by_plane += !best_range.is_empty();
    return -1;
}

ClusterAttemptResult ClusterAttempt::try_paint(const PixelRect& B, const Mark* marks, size_t n,
                                               const SubpatchArena& coefs, PixelScratch& pixel,
                                               RenderStats& st) {
    int levels_over = 0;
    const MarkSpan m{marks, n, coefs};
    Certified c;
    c.patch = nearest_patch(marks, n, c.box);
    if (c.patch < 0) return {RenderStats::none, levels_over};
    const int cause = certify(B, m, c, st); // step 7
    if (cause >= 0) return {cause, levels_over};
    const StepClock shading(st.shade_seconds);
    // From here on step 7 holds for B: a failure says so (certified_pixels.h).
    auto proven = [&](int why) {
        return ClusterAttemptResult{why, levels_over, true, c.patch, c.box};
    };
    // Step 8: SHADE (cluster_shade.h).
    const ClusterShading cs = shader_.enclose_intensity(c.patch, c.e, c.world, st);
    if (!cs.decided) return proven(RenderStats::light);
    const auto& I = cs.I;
    int lo[3], hi[3];
    bool two = false;
    for (int k = 0; k < 3; ++k) {
        if (!I[k].is_finite()) return proven(RenderStats::span);
        lo[k] = quantise(I[k].lo(), levels_);
        hi[k] = quantise(I[k].hi(), levels_);
        levels_over = std::max(levels_over, hi[k] - lo[k]);
    }
    bool span = false;
    for (int k = 0; k < 3; ++k) {
        span |= hi[k] - lo[k] > (dither_ ? 1 : 0);
        two |= hi[k] > lo[k];
    }
    // Step 9 with a second-order criterion (second_order.h) where the
    // enclosure spans too many levels: primary clusters only (reflected
    // and refracted light keeps the plain rule), B not tiny.
    std::array<double, 3> corner[4];
    if (span) {
        if (cs.secondary || B.count() < kSecondOrderArea) return proven(RenderStats::span);
        if (!second_order_corners(B, c, cs, pixel, st, levels_over, corner))
            return proven(RenderStats::span);
    }
    st.secondary_clusters += cs.secondary;
    st.shadowed_clusters += cs.shadowed;
    if (two) {
        if (!span) corner_rays(B, c, I, pixel, st, corner);
        paint_bilinear(B, corner, lo, hi);
    } else {
        paint_level(B, lo);
    }
    ++st.subscreens_by_size[B.count()];
    return {-1, levels_over};
}

// Step 9's second-order rule (second_order.h) for B: true with the corner
// intensities to paint from; false when its bound is too wide (levels_over
// cleared where B's children may pass).
bool ClusterAttempt::second_order_corners(const PixelRect& B, const Certified& c,
                                          const ClusterShading& cs, PixelScratch& pixel,
                                          RenderStats& st, int& levels_over,
                                          std::array<double, 3> corner[4]) {
    const ProjectedPatch& pp = ps_.patches[c.patch];
    ++st.second_order_attempts;
    const CornerPixels corners{{ps_.frame.screen_a(B.x0 + 0.5), ps_.frame.screen_a(B.x1 + 0.5)},
                               {ps_.frame.screen_b(B.y0 + 0.5), ps_.frame.screen_b(B.y1 + 0.5)}};
    const SecondOrder so =
        second_order({pp, c.box, cs.e, sys_}, {*cs.lighting, ps_.lighting.materials[pp.material]},
                     corners, {levels_, dither_}, pixel.sys, st);
    if (!so.paint) {
        // Halving B quarters the bound: children may pass where B failed.
        if (so.error_levels < 4 * (dither_ ? 0.5 : 1.0)) levels_over = 0;
        return false;
    }
    ++st.second_order_painted;
    st.second_order_pixels += B.count();
    for (int k = 0; k < 4; ++k) corner[k] = so.corner[k];
    return true;
}

// Step 9 with remark 2: the intensities of B's corner rays (I's midpoints
// where a corner's solve finds no hit).
void ClusterAttempt::corner_rays(const PixelRect& B, const Certified& c,
                                 const std::array<Interval, 3>& I, PixelScratch& pixel,
                                 RenderStats& st, std::array<double, 3> corner[4]) {
    const ProjectedPatch& pp = ps_.patches[c.patch];
    const int cx[4] = {B.x0, B.x1, B.x0, B.x1}, cy[4] = {B.y0, B.y0, B.y1, B.y1};
    const Mark only{c.patch, c.box, {}};
    for (int k = 0; k < 4; ++k) {
        double cs, ct;
        const double ca = ps_.frame.screen_a(cx[k] + 0.5), cb = ps_.frame.screen_b(cy[k] + 0.5);
        if (newton_corner(pp.patch, ca, cb, c.box, cs, ct)) {
            ++st.primary_rays;
            corner[k] = shade_hit(ps_, scene_, ts_, PixelHit{c.patch, cs, ct, 0});
            continue;
        }
        const PixelHit h = solve_pixel(ps_, ca, cb, {&only, 1}, pixel, st);
        if (h.patch < 0) {
            for (int i = 0; i < 3; ++i) corner[k][i] = I[i].mid();
        } else {
            corner[k] = shade_hit(ps_, scene_, ts_, h);
        }
    }
}

// B painted with one level per channel (its enclosure's).
void ClusterAttempt::paint_level(const PixelRect& B, const int lo[3]) {
    for (int y = B.y0; y <= B.y1; ++y)
        for (int x = B.x0; x <= B.x1; ++x) {
            for (int c = 0; c < 3; ++c) image_.at(x, y, c) = static_cast<std::uint16_t>(lo[c]);
            image_.surface_at(x, y) = 1;
        }
}

// B painted with the bilinear form of its corner intensities plus dither,
// within the enclosure's levels [lo, hi] (step 9, remark 2).
void ClusterAttempt::paint_bilinear(const PixelRect& B, const std::array<double, 3> corner[4],
                                    const int lo[3], const int hi[3]) {
    const BilinearForm form{corner, levels_};
    const double wx = std::max(1, B.x1 - B.x0), wy = std::max(1, B.y1 - B.y0);
    for (int y = B.y0; y <= B.y1; ++y) {
        const double fy = (y - B.y0) / wy;
        for (int x = B.x0; x <= B.x1; ++x) {
            const double fx = (x - B.x0) / wx;
            image_.surface_at(x, y) = 1;
            for (int c = 0; c < 3; ++c)
                image_.at(x, y, c) = static_cast<std::uint16_t>(
                    form.level(c, fx, fy, dither_ ? dither(x, y, c) : 0.0, lo[c], hi[c]));
        }
    }
}

} // namespace seamless
