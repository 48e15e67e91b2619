// SPDX-License-Identifier: MIT
// INTRACY (paper section 7) for primary rays and direct light.
//
// The screen is prepartitioned into 8 x 8 parts (remark 4), each handled with
// its own stack of sub-screens B and run in parallel. For each B:
//  step 3: every marked patch is compared with B by hull (remark 1 of Prop. 11
//          in its primary-ray form), then its (s, t) intervals are narrowed by
//          Theorem 10 (remark 3: at the interval bounds, and at the midpoints
//          where a silhouette is possible, which may separate the patch in two);
//          a patch whose intervals become empty is unmarked;
//  step 5: B shrinks to the hull of the projections of the marked patches; the
//          rest of B is background, certainly;
//  step 6: a one-pixel B is solved on every marked patch, nearest first
//          (remark 1), by certified Newton with the covering method as the
//          fallback (pixel_solve.h); so is every pixel of a B of at most
//          RenderOptions::pixel_subscreen pixels, without a cluster attempt;
//  step 7: otherwise, if the nearest marked patch is q-separated from all the
//          others (a nearest q-connected set, Theorem 10 remark 4), and the
//          Hansen-Sengupta operator over the whole cluster maps its box into
//          its interior (Theorem 6 iii for every ray of B at once: each ray
//          hits it, exactly once in the box), then every ray of B sees that
//          patch and nothing else;
//  step 8: SHADE encloses the intensity of B over the hulls of point and normal;
//  step 9: if every channel's enclosure holds at most two levels, B is painted
//          with the bilinear form of its four corner intensities (corner rays by
//          Hansen-Sengupta, remark 2) plus dither in [-0.5, 0.5], kept within
//          the enclosure's levels; without dithering B must hold one level;
//  step 10: otherwise B is split into four (remark 3), or two, and pushed.
// Step 7's certificate replaces the paper's conditions a)-c) of remark 4 with a
// proof: a pixel painted from a cluster is never wrong by more than one level
// (the enclosure holds the true intensity), and background is never painted
// where a patch is hit.
#include <seamless/render/mark.h>
#include <seamless/render/parallel.h>
#include <seamless/render/pixel_solve.h>
#include <seamless/render/primary_cluster.h>
#include <seamless/render/projection.h>
#include <seamless/render/ray_cluster.h>
#include <seamless/render/render.h>
#include <seamless/render/shading.h>
#include <seamless/render/trace.h>

#include <seamless/interval/hansen_sengupta.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <ctime>
#include <memory>
#include <optional>

namespace seamless {
namespace {

// CPU seconds of the calling thread: on a shared machine a step's own cost,
// not the time other jobs held the core.
double thread_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// Adds the thread's CPU seconds from construction to destruction to `acc` (--stats).
class StepClock {
  public:
    explicit StepClock(double& acc) : acc_(acc), t0_(thread_seconds()) {}
    StepClock(const StepClock&) = delete;
    StepClock& operator=(const StepClock&) = delete;
    ~StepClock() { acc_ += thread_seconds() - t0_; }

  private:
    double& acc_;
    double t0_;
};

struct SubScreen {
    int x0, y0, x1, y1;   // inclusive pixel range
    size_t offset, count; // its marks in the arena
};

// SHADE for one ray at an exact hit (steps 6 and 7's corner rays). With
// secondary rays in play (a triangle scene), shadows, reflection and refraction
// are traced against the triangles (section 7, SHADE); the local illumination
// model is the same either way.
std::array<double, 3> shade_hit(const ProjectedScene& ps, const Scene& scene,
                                const TriangleScene* ts, const PixelHit& h) {
    Vec3 P, N;
    const ProjectedPatch& pp = ps.patches[h.patch];
    surface_frame(pp.patch, h.s, h.t, P, N);
    if (!ts)
        return shade<double>(ps.lighting, ps.lighting.materials[pp.material], to_v3(P), to_v3(N),
                             Vec3{});
    const Vec3 Pw = ps.frame.to_world(P);
    return shade_ray(scene, *ts, Pw, normalize(ps.frame.to_world_direction(N)), pp.material,
                     h.patch, normalize(ps.frame.eye - Pw), 0);
}

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

class PartRenderer {
  public:
    PartRenderer(const ProjectedScene& ps, const Scene& scene, const TriangleScene* ts,
                 const RenderOptions& opt, Image& image, int levels)
        : ps_(ps), scene_(scene), ts_(ts), opt_(opt), image_(image), levels_(levels),
          scene_diagonal_(next_up(norm(control_box(scene.model).extent()))),
          lighting_depth_(static_cast<size_t>(scene.max_depth) + 1) {
        const Vec3 bg = ps.lighting.background;
        for (int c = 0; c < 3; ++c) bg_[c] = static_cast<std::uint16_t>(quantise(bg[c], levels));
    }

    void run(int x0, int y0, int x1, int y1, RenderStats& st) {
        arena_.clear();
        stack_.clear();
        for (size_t k = 0; k < ps_.patches.size(); ++k)
            arena_.push_back({static_cast<int>(k), ParamBox{}, ps_.patches[k].hull});
        stack_.push_back({x0, y0, x1, y1, 0, arena_.size()});
        const long long enclosures0 = range_enclosure_count();
        while (!stack_.empty()) {
            SubScreen B = stack_.back();
            stack_.pop_back();
            arena_.resize(B.offset + B.count);
            ++st.subscreens;
            step(B, st);
        }
        st.range_enclosures += range_enclosure_count() - enclosures0;
        st.shade_seconds -= st.secondary_seconds; // reported apart
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
    void count(const SubScreen& B, RenderStats& st) {
        ++st.subscreens_by_size[static_cast<long long>(B.x1 - B.x0 + 1) * (B.y1 - B.y0 + 1)];
    }

    void step(SubScreen B, RenderStats& st) {
        const bool thin = B.x0 == B.x1 && B.y0 == B.y1;
        const long long area = static_cast<long long>(B.x1 - B.x0 + 1) * (B.y1 - B.y0 + 1);
        if (!thin && area <= opt_.pixel_subscreen) {
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
            // cannot narrow a box (its derivative hull holds 0, near a silhouette) and
            // the box still projects far beyond B, it is bisected and both halves go on.
            work_.clear();
            work_.push_back(arena_[k]);
            int budget = kMaxBisections;
            while (!work_.empty()) {
                Mark m = work_.back();
                work_.pop_back();
                const ProjectedPatch& pp = ps_.patches[m.patch];
                // Hull comparison with the hull the mark brought from its parent.
                const IVec3& P = m.hull;
                if (!(P[2].hi() > 0)) continue; // behind the eye
                if (!(P[0] - a * P[2]).contains(0.0) || !(P[1] - b * P[2]).contains(0.0)) continue;
                if (thin) {
                    arena_.push_back(m);
                    continue;
                }
                cluster_system(pp.forms, a, b, sys_);
                ++st.marks_narrowed;
                if (!narrow(sys_, m.box)) continue;
                const IVec3 Q = enclose_point(pp.forms, m.box);
                m.hull = Q;
                const bool wide = !(Q[2].lo() > 0) ||
                                  (Q[0] / Q[2]).width() > 2 * (a.width() + pitch_a) ||
                                  (Q[1] / Q[2]).width() > 2 * (b.width() + pitch_b);
                if (wide && budget > 0 && std::max(m.box.s.width(), m.box.t.width()) > 1e-9) {
                    --budget;
                    ++st.mark_bisections;
                    Mark lo = m, hi = m;
                    if (m.box.s.width() >= m.box.t.width()) {
                        const double sm = m.box.s.mid();
                        lo.box.s = {m.box.s.lo(), sm};
                        hi.box.s = {sm, m.box.s.hi()};
                    } else {
                        const double tm = m.box.t.mid();
                        lo.box.t = {m.box.t.lo(), tm};
                        hi.box.t = {tm, m.box.t.hi()};
                    }
                    work_.push_back(hi);
                    work_.push_back(lo);
                    continue;
                }
                // Remark 3: where a silhouette is possible the patch is separated. In
                // the projected problem the silhouette is where the Jacobian of G
                // (the projected normal's z component) vanishes.
                const Interval J = horner(sys_.Gs, 0, m.box) * horner(sys_.Gt, 1, m.box) -
                                   horner(sys_.Gs, 1, m.box) * horner(sys_.Gt, 0, m.box);
                ParamBox parts[2];
                const int n =
                    J.contains(0.0) ? separate(sys_, m.box, parts) : (parts[0] = m.box, 1);
                for (int i = 0; i < n; ++i) arena_.push_back({m.patch, parts[i], Q});
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
            paint_single_pixel(B, first, nmarks, st);
            return;
        }
        // Step 5: B shrinks to the hull of the projections of the marked patches.
        if (improve(B, first, nmarks, st)) return;
        // Step 7: a nearest q-separated patch that certainly covers B.
        if (try_paint(B, first, nmarks, st)) return;
        // Step 10: split into four while possible (remark 3), else two.
        const int w = B.x1 - B.x0 + 1, h = B.y1 - B.y0 + 1;
        const int xm = B.x0 + w / 2 - 1, ym = B.y0 + h / 2 - 1;
        SubScreen kids[4];
        int nk = 0;
        if (w > 1 && h > 1) {
            kids[nk++] = {B.x0, B.y0, xm, ym, 0, 0};
            kids[nk++] = {xm + 1, B.y0, B.x1, ym, 0, 0};
            kids[nk++] = {B.x0, ym + 1, xm, B.y1, 0, 0};
            kids[nk++] = {xm + 1, ym + 1, B.x1, B.y1, 0, 0};
        } else if (w > 1) {
            kids[nk++] = {B.x0, B.y0, xm, B.y1, 0, 0};
            kids[nk++] = {xm + 1, B.y0, B.x1, B.y1, 0, 0};
        } else {
            kids[nk++] = {B.x0, B.y0, B.x1, ym, 0, 0};
            kids[nk++] = {B.x0, ym + 1, B.x1, B.y1, 0, 0};
        }
        // Each child gets the marks of B (already at the top of the arena for
        // the first; copies for the others). Pushed in reverse so the first is next.
        for (int i = nk - 1; i >= 0; --i) {
            kids[i].offset = first;
            kids[i].count = nmarks;
        }
        // All children share one mark list: a child's processing truncates the
        // arena to offset+count before appending, so the list survives for the next.
        for (int i = nk - 1; i >= 0; --i) stack_.push_back(kids[i]);
    }

    // A small B is solved pixel by pixel from its marks (those of its parent),
    // without a cluster attempt: a few certified Newton solves cost less than
    // narrowing, certificate and SHADE for a cluster of a handful of pixels.
    void paint_pixels(const SubScreen& B, RenderStats& st) {
        for (int y = B.y0; y <= B.y1; ++y)
            for (int x = B.x0; x <= B.x1; ++x) {
                const double a = ps_.frame.screen_a(x + 0.5), b = ps_.frame.screen_b(y + 0.5);
                const size_t first = arena_.size();
                for (size_t k = B.offset; k < B.offset + B.count; ++k) {
                    const Mark m = arena_[k]; // a copy: push_back may move the arena
                    const IVec3& P = m.hull;
                    if (!(P[2].hi() > 0)) continue; // behind the eye
                    if (!(P[0] - Interval(a) * P[2]).contains(0.0) ||
                        !(P[1] - Interval(b) * P[2]).contains(0.0))
                        continue;
                    arena_.push_back(m);
                }
                const SubScreen pixel{x, y, x, y, 0, 0};
                if (arena_.size() == first) {
                    paint_background(x, y, x, y, st);
                    count(pixel, st);
                } else {
                    paint_single_pixel(pixel, first, arena_.size() - first, st);
                }
                arena_.resize(first);
            }
    }

    // Step 6: a one-pixel B, solved by Hansen-Sengupta on its marked patches.
    void paint_single_pixel(const SubScreen& B, size_t first, size_t n, RenderStats& st) {
        const StepClock clock(st.single_pixel_seconds);
        ++st.single_pixels;
        const PixelHit h =
            solve_pixel(ps_, ps_.frame.screen_a(B.x0 + 0.5), ps_.frame.screen_b(B.y0 + 0.5),
                        &arena_[first], n, pixel_, st);
        if (h.patch < 0) {
            paint_background(B.x0, B.y0, B.x0, B.y0, st);
        } else {
            const auto I = shade_hit(ps_, scene_, ts_, h);
            for (int c = 0; c < 3; ++c)
                image_.at(B.x0, B.y0, c) = static_cast<std::uint16_t>(quantise(I[c], levels_));
            image_.surface_at(B.x0, B.y0) = 1;
        }
        count(B, st);
    }

    // Step 5. Returns true if B was finished (all background).
    bool improve(SubScreen& B, size_t first, size_t n, RenderStats& st) {
        Interval ha = Interval::empty(), hb = Interval::empty();
        for (size_t k = first; k < first + n; ++k) {
            const IVec3& P = arena_[k].hull;
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
            paint_single_pixel(B, first, n, st);
            return true;
        }
        return false;
    }

    // SHADE step 2 for a cluster: the cluster of rays from each light to the
    // hull of the intersection points meets no triangle but those of the
    // patch itself (step 1 marks them; Proposition 11 with remarks 1-2).
    // Camera-space interval vector to world space (outward rounded).
    IVec<3> to_world(const IVec3& c, bool point) const {
        const CameraFrame& f = ps_.frame;
        IVec<3> w;
        for (int i = 0; i < 3; ++i)
            w[i] = (point ? Interval(f.eye[i]) : Interval(0.0)) + c[0] * Interval(f.right[i]) -
                   c[1] * Interval(f.up[i]) + c[2] * Interval(f.forward[i]);
        return w;
    }

    // Reflected directions D - 2 (D.N / N.N) N of a cluster (SHADE step 3.1).
    static bool reflect_directions(const IVec<3>& D, const IVec<3>& N, IVec<3>& R) {
        const Interval dn = D[0] * N[0] + D[1] * N[1] + D[2] * N[2];
        const Interval nn = sqr(N[0]) + sqr(N[1]) + sqr(N[2]);
        if (!(nn.lo() > 0)) return false;
        const Interval k = Interval(2.0) * dn / nn;
        for (int i = 0; i < 3; ++i) R[i] = D[i] - k * N[i];
        return true;
    }

    // Refracted directions of a cluster with incoming directions D at normals N
    // (SHADE step 4), as trace.cpp does for one ray: entering when the ray
    // comes from the side N points to, Snell's law, total internal reflection.
    // false when the side or total reflection is undecided for the cluster.
    static bool refract_directions(const IVec<3>& D, const IVec<3>& N, double ior, IVec<3>& T) {
        const Interval dd = sqr(D[0]) + sqr(D[1]) + sqr(D[2]);
        const Interval nn = sqr(N[0]) + sqr(N[1]) + sqr(N[2]);
        if (!(dd.lo() > 0) || !(nn.lo() > 0)) return false;
        const Interval dl = sqrt(dd), nl = sqrt(nn);
        IVec<3> v, n; // unit view (towards the viewer) and unit normal
        for (int i = 0; i < 3; ++i) {
            v[i] = -D[i] / dl;
            n[i] = N[i] / nl;
        }
        const Interval cos_v = v[0] * n[0] + v[1] * n[1] + v[2] * n[2];
        if (cos_v.contains(0.0)) return false;
        const bool entering = cos_v.lo() > 0;
        if (!entering)
            for (int i = 0; i < 3; ++i) n[i] = -n[i];
        const Interval cos_i = abs(cos_v);
        const double eta = entering ? 1 / ior : ior;
        const Interval k =
            Interval(1.0) - Interval(eta) * Interval(eta) * (Interval(1.0) - sqr(cos_i));
        if (k.contains(0.0)) return false;
        if (k.hi() < 0) return reflect_directions(D, N, T); // total internal reflection
        const Interval f = Interval(eta) * cos_i - sqrt(k);
        for (int i = 0; i < 3; ++i) T[i] = -Interval(eta) * v[i] + f * n[i];
        return true;
    }

    // SHADE for a cluster of secondary rays from the box `origin` in the
    // directions `dir`, leaving patch `skip_patch`, whose hits have recursion
    // depth `depth` (section 7, steps 3.2-3.5 and 4). Step 3.3: when the
    // cluster certainly meets no triangle, it sees the background. Step 3.4,
    // for a nearest q-connected set of one triangle: when one triangle
    // certainly meets every ray and no other triangle may be met before it,
    // SHADE recurses on the hull of the meeting points with the interpolated
    // corner normals (lights by step 2, seen from the rays' origins; its own
    // reflection and refraction while depth < max_depth). Otherwise false:
    // B is split (step 3.5).
    bool secondary_cluster(const IVec<3>& origin, const IVec<3>& dir, int skip_patch, int depth,
                           std::array<Interval, 3>& out) {
        const double dmin = sqrt(sqr(dir[0]) + sqr(dir[1]) + sqr(dir[2])).lo();
        if (!(dmin > 0)) return false;
        RayCluster rc;
        rc.origin = origin;
        rc.direction = dir;
        // q up to diag / |dir| carries every ray across the whole scene.
        rc.q = Interval(0.0, next_up(next_up(scene_diagonal_ / dmin) * 1.001));
        const ClusterHull ch(rc);
        const auto& M = ts_->tess.mesh;
        int cover = -1, candidates = 0;
        Interval cq, cb, cd;
        visit_candidate_triangles(
            ts_->tess.trees, [&](const Box3& b) { return ch.may_meet(b); },
            [&](int t) {
                if (ts_->triangle_patch[t] == skip_patch) return;
                const auto& tri = M.triangles[t];
                if (!may_hit_triangle(rc, M.positions[tri[0]], M.positions[tri[1]],
                                      M.positions[tri[2]]))
                    return;
                ++candidates;
                Interval q, beta, delta;
                if (covers_triangle(rc, M.positions[tri[0]], M.positions[tri[1]],
                                    M.positions[tri[2]], q, &beta, &delta) &&
                    q.lo() * dmin > 2 * ts_->ray_epsilon && (cover < 0 || q.hi() < cq.lo())) {
                    cover = t;
                    cq = q;
                    cb = beta;
                    cd = delta;
                }
            });
        if (candidates == 0) { // step 3.3
            const Vec3 bg = scene_.background;
            for (int c = 0; c < 3; ++c) out[c] = Interval(bg[c]);
            return true;
        }
        if (cover < 0) return false;
        // Nearest: no other triangle may be met up to the covering one.
        RayCluster before = rc;
        before.q = Interval(0.0, cq.hi());
        const ClusterHull chb(before);
        bool other = false;
        visit_candidate_triangles(
            ts_->tess.trees, [&](const Box3& b) { return !other && chb.may_meet(b); },
            [&](int t) {
                if (other || t == cover || ts_->triangle_patch[t] == skip_patch) return;
                const auto& tri = M.triangles[t];
                other = may_hit_triangle(before, M.positions[tri[0]], M.positions[tri[1]],
                                         M.positions[tri[2]]);
            });
        if (other) return false;
        const Material& hm = scene_.materials[ts_->triangle_material[cover]];
        const int hit_patch = ts_->triangle_patch[cover];
        // The meeting points and the interpolated normals over (beta, delta).
        const auto& tri = M.triangles[cover];
        const Interval w[3] = {Interval(1.0) - cb - cd, cb, cd};
        IVec<3> H, HN;
        for (int i = 0; i < 3; ++i) {
            H[i] = Interval(0.0);
            HN[i] = Interval(0.0);
            for (int v = 0; v < 3; ++v) {
                H[i] += w[v] * Interval(M.positions[tri[v]][i]);
                HN[i] += w[v] * Interval(M.corner_normals[cover][v][i]);
            }
        }
        Scene& lighting = lighting_depth_.at(depth); // sized max_depth + 1: never reallocated here
        if (!lights_for_cluster(H, hit_patch, hm, lighting.lights)) return false;
        lighting.ambient = scene_.ambient;
        const V3<Interval> HP{H[0], H[1], H[2]}, HNv{HN[0], HN[1], HN[2]},
            eye{origin[0], origin[1], origin[2]};
        out = shade<Interval>(lighting, hm, HP, HNv, eye);
        if (depth < scene_.max_depth && (hm.reflect > 0 || hm.transmit > 0)) {
            // The hit's own steps 3 and 4, from the meeting points onwards.
            IVec<3> D;
            for (int i = 0; i < 3; ++i) D[i] = H[i] - origin[i];
            std::array<Interval, 3> more;
            if (hm.reflect > 0) {
                IVec<3> R;
                if (!reflect_directions(D, HN, R) ||
                    !secondary_cluster(H, R, hit_patch, depth + 1, more))
                    return false;
                for (int c = 0; c < 3; ++c) out[c] += Interval(hm.reflect) * more[c];
            }
            if (hm.transmit > 0) {
                IVec<3> T;
                if (!refract_directions(D, HN, hm.ior, T) ||
                    !secondary_cluster(H, T, hit_patch, depth + 1, more))
                    return false;
                for (int c = 0; c < 3; ++c) out[c] += Interval(hm.transmit) * more[c];
            }
            for (int c = 0; c < 3; ++c) out[c] = clamp01(out[c]);
        }
        return true;
    }

    // SHADE step 2 for a cluster: which lights reach every point of B. The
    // cluster of rays from a light to the hull of the intersection points is
    // compared with the triangles but those of the patch itself (step 1 marks
    // them; Proposition 11 with remarks 1-2). A light is visible when no
    // triangle may meet the cluster, blocked when one triangle certainly meets
    // every ray between the light and the points (Theorem 6 iii), and
    // undecided otherwise (then B is split). Fills `visible` with the lights
    // that reach B; returns false when some light is undecided.
    bool lights_for_cluster(const IVec<3>& Pw, int patch, const Material& mat,
                            std::vector<Light>& visible) {
        visible.clear();
        if (mat.diffuse == 0 && mat.specular == 0) return true;
        for (size_t l = 0; l < scene_.lights.size(); ++l) {
            const Light& light = scene_.lights[l];
            if (!light.on()) continue;
            RayCluster rc;
            for (int i = 0; i < 3; ++i) {
                rc.origin[i] = Interval(light.position[i]);
                rc.direction[i] = Pw[i] - Interval(light.position[i]);
            }
            rc.q = Interval(0.0, 1.0);
            // A single ray's shadow test starts ray_epsilon from the point: a
            // certain blocker must meet every ray before that.
            const Interval dist2 =
                sqr(rc.direction[0]) + sqr(rc.direction[1]) + sqr(rc.direction[2]);
            const double q_max = 1 - 2 * ts_->ray_epsilon / std::sqrt(std::max(dist2.lo(), 1e-300));
            const ClusterHull ch(rc);
            bool maybe = false, blocked = false;
            visit_candidate_triangles(
                ts_->tess.trees, [&](const Box3& b) { return !blocked && ch.may_meet(b); },
                [&](int t) {
                    if (blocked || ts_->triangle_patch[t] == patch) return;
                    const auto& tri = ts_->tess.mesh.triangles[t];
                    const auto& V = ts_->tess.mesh.positions;
                    if (!may_hit_triangle(rc, V[tri[0]], V[tri[1]], V[tri[2]])) return;
                    maybe = true;
                    Interval q;
                    if (covers_triangle(rc, V[tri[0]], V[tri[1]], V[tri[2]], q) && q.lo() > 0 &&
                        q.hi() < q_max)
                        blocked = true;
                });
            if (blocked) {
                ++blocked_lights_;
                continue;
            }
            if (maybe) return false;
            visible.push_back(light);
        }
        return true;
    }

    // Steps 7 to 9. Returns true if B was painted.
    bool try_paint(const SubScreen& B, size_t first, size_t n, RenderStats& st) {
        // Depth (q) intervals. The marks of one patch (halves of bisections,
        // separated pieces) are taken together: their hull box holds every hit
        // of that patch in B. The nearest patch must be q-separated from all
        // other marks (a nearest q-connected set of one patch).
        int best_patch = -1;
        double best_lo = std::numeric_limits<double>::infinity();
        for (size_t k = first; k < first + n; ++k) {
            const Interval q = arena_[k].hull[2];
            if (q.lo() < best_lo) {
                best_lo = q.lo();
                best_patch = arena_[k].patch;
            }
        }
        if (best_patch < 0) return false;
        ParamBox box{Interval::empty(), Interval::empty()};
        for (size_t k = first; k < first + n; ++k)
            if (arena_[k].patch == best_patch) {
                box.s = hull(box.s, arena_[k].box.s);
                box.t = hull(box.t, arena_[k].box.t);
            }
        const ProjectedPatch& pp = ps_.patches[best_patch];
        {
            const StepClock clock(st.certify_seconds);
            const Interval a = screen_a(B.x0, B.x1), b = screen_b(B.y0, B.y1);
            cluster_system(pp.forms, a, b, sys_);
            if (!certify_cluster(sys_, box, &st.hs_steps)) return false;
            const Interval qbest = enclose_point(pp.forms, box)[2];
            if (!(qbest.lo() > 0)) return false;
            for (size_t k = first; k < first + n; ++k) {
                if (arena_[k].patch == best_patch) continue;
                const Interval q = arena_[k].hull[2];
                if (q.lo() <= qbest.hi()) return false; // not a nearest q-connected set of one
            }
        }
        const StepClock shading(st.shade_seconds);
        const Mark m{best_patch, box, {}};
        // Step 8: SHADE over the hulls of the intersection points and normals.
        const PatchEnclosure e = enclose(pp.forms, box);
        const V3<Interval> P{e.point[0], e.point[1], e.point[2]};
        const V3<Interval> N{e.normal[0], e.normal[1], e.normal[2]};
        const Material& mat = ps_.lighting.materials[pp.material];
        // With secondary rays, only the lights that reach B count (step 2), and
        // mirrors and glass add their reflected and refracted clusters (steps 3, 4).
        blocked_lights_ = 0;
        if (ts_ && !lights_for_cluster(to_world(e.point, true), m.patch, mat, lighting_.lights))
            return false;
        const bool shadowed = blocked_lights_ > 0;
        lighting_.ambient = ps_.lighting.ambient;
        if (ts_)
            for (Light& l : lighting_.lights) l.position = ps_.frame.to_camera(l.position);
        auto I = shade<Interval>(ts_ ? lighting_ : ps_.lighting, mat, P, N, Vec3{});
        const bool secondary = ts_ && (mat.reflect > 0 || mat.transmit > 0) && scene_.max_depth > 0;
        if (secondary) {
            // The secondary terms only add to the local ones: if those alone
            // span too many levels, split before tracing any cluster.
            for (int c = 0; c < 3; ++c)
                if (quantise(I[c].hi(), levels_) - quantise(I[c].lo(), levels_) >
                    (opt_.dither ? 1 : 0))
                    return false;
            const IVec<3> Pw = to_world(e.point, true), Nw = to_world(e.normal, false);
            IVec<3> D;
            for (int i = 0; i < 3; ++i) D[i] = Pw[i] - Interval(ps_.frame.eye[i]);
            std::array<Interval, 3> more;
            if (mat.reflect > 0) {
                IVec<3> R;
                const StepClock clock(st.secondary_seconds);
                if (!reflect_directions(D, Nw, R) || !secondary_cluster(Pw, R, m.patch, 1, more))
                    return false;
                for (int c = 0; c < 3; ++c) I[c] += Interval(mat.reflect) * more[c];
            }
            if (mat.transmit > 0) {
                IVec<3> T;
                const StepClock clock(st.secondary_seconds);
                if (!refract_directions(D, Nw, mat.ior, T) ||
                    !secondary_cluster(Pw, T, m.patch, 1, more))
                    return false;
                for (int c = 0; c < 3; ++c) I[c] += Interval(mat.transmit) * more[c];
            }
            for (int c = 0; c < 3; ++c) I[c] = clamp01(I[c]);
        }
        int lo[3], hi[3];
        bool two = false;
        for (int c = 0; c < 3; ++c) {
            if (!I[c].is_finite()) return false;
            lo[c] = quantise(I[c].lo(), levels_);
            hi[c] = quantise(I[c].hi(), levels_);
            if (hi[c] - lo[c] > (opt_.dither ? 1 : 0)) return false;
            two |= hi[c] > lo[c];
        }
        st.secondary_clusters += secondary;
        st.shadowed_clusters += shadowed;
        if (!two) {
            for (int y = B.y0; y <= B.y1; ++y)
                for (int x = B.x0; x <= B.x1; ++x) {
                    for (int c = 0; c < 3; ++c)
                        image_.at(x, y, c) = static_cast<std::uint16_t>(lo[c]);
                    image_.surface_at(x, y) = 1;
                }
            count(B, st);
            return true;
        }
        // Step 9 with remark 2: corner rays, bilinear form, dither.
        std::array<double, 3> corner[4];
        const int cx[4] = {B.x0, B.x1, B.x0, B.x1}, cy[4] = {B.y0, B.y0, B.y1, B.y1};
        const Mark only{m.patch, box, {}};
        for (int k = 0; k < 4; ++k) {
            double cs, ct;
            const double ca = ps_.frame.screen_a(cx[k] + 0.5), cb = ps_.frame.screen_b(cy[k] + 0.5);
            if (newton_corner(pp.patch, ca, cb, box, cs, ct)) {
                ++st.primary_rays;
                corner[k] = shade_hit(ps_, scene_, ts_, PixelHit{m.patch, cs, ct, 0});
                continue;
            }
            const PixelHit h = solve_pixel(ps_, ca, cb, &only, 1, pixel_, st);
            if (h.patch < 0) {
                for (int c = 0; c < 3; ++c) corner[k][c] = I[c].mid();
            } else {
                corner[k] = shade_hit(ps_, scene_, ts_, h);
            }
        }
        const double wx = std::max(1, B.x1 - B.x0), wy = std::max(1, B.y1 - B.y0);
        for (int y = B.y0; y <= B.y1; ++y) {
            const double fy = (y - B.y0) / wy;
            for (int x = B.x0; x <= B.x1; ++x) {
                const double fx = (x - B.x0) / wx;
                image_.surface_at(x, y) = 1;
                for (int c = 0; c < 3; ++c) {
                    const double v = (1 - fy) * ((1 - fx) * corner[0][c] + fx * corner[1][c]) +
                                     fy * ((1 - fx) * corner[2][c] + fx * corner[3][c]);
                    long level = std::lround(clamp01(v) * (levels_ - 1) + dither(x, y, c));
                    level = std::clamp<long>(level, lo[c], hi[c]);
                    image_.at(x, y, c) = static_cast<std::uint16_t>(level);
                }
            }
        }
        count(B, st);
        return true;
    }

    const ProjectedScene& ps_;
    const Scene& scene_;
    const TriangleScene* ts_; // null: no secondary rays in play
    const RenderOptions& opt_;
    Image& image_;
    int levels_;
    double scene_diagonal_; // bounds every segment inside the scene (convex hull property)
    std::uint16_t bg_[3];
    static constexpr int kMaxBisections = 64; // per marked patch and sub-screen
    std::vector<Mark> arena_, work_;
    std::vector<SubScreen> stack_;
    PixelScratch pixel_;
    Scene lighting_; // scratch: ambient and the lights that reach a cluster, camera coordinates
    // the same for secondary clusters' hits, one per depth, world coordinates
    std::vector<Scene> lighting_depth_;
    int blocked_lights_ = 0; // lights certainly blocked in the last lights_for_cluster
    ClusterSystem sys_;
};

} // namespace

Image render_intracy(const Scene& scene, const RenderOptions& opt, RenderStats& st) {
    const int W = opt.width > 0 ? opt.width : scene.camera.width;
    const int H = opt.height > 0 ? opt.height : scene.camera.height;
    const int L = opt.levels > 0 ? opt.levels : scene.levels;
    const auto t0 = std::chrono::steady_clock::now();
    const ProjectedScene ps = project_scene(scene, W, H); // step 1
    // Secondary rays (SHADE steps 2-4) need the triangles and patch trees; a
    // scene without lit diffuse or specular surfaces and without mirrors or
    // glass needs none, and gets none.
    std::unique_ptr<TriangleScene> ts;
    if (needs_secondary_rays(scene)) {
        ts = std::make_unique<TriangleScene>(build_triangle_scene(scene));
        st.triangles = ts->tess.mesh.triangle_count();
    }
    st.precalc_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    st.patches = static_cast<long long>(ps.patches.size());
    Image image(W, H, L);

    // Remark 4: 8 x 8 congruent parts (fewer when the image is smaller).
    const int px = std::min(opt.prepartition, W), py = std::min(opt.prepartition, H);
    const int parts = px * py;
    std::vector<RenderStats> part_stats(parts);
    std::atomic<int> done{0};
    auto work = [&](int p) {
        const int i = p % px, j = p / px;
        const int x0 = i * W / px, x1 = (i + 1) * W / px - 1;
        const int y0 = j * H / py, y1 = (j + 1) * H / py - 1;
        PartRenderer r(ps, scene, ts.get(), opt, image, L);
        r.run(x0, y0, x1, y1, part_stats[p]);
        const int d = ++done;
        if (opt.progress) opt.progress(static_cast<double>(d) / parts);
    };
    for_each_item(parts, opt.threads, work);
    for (const RenderStats& s : part_stats) st.merge(s);
    return image;
}

} // namespace seamless
