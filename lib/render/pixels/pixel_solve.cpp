// SPDX-License-Identifier: MIT
#include <seamless/render/pixels/pixel_solve.h>
#include <seamless/render/subscreen/shared_marks.h>

#include <seamless/interval/hansen_sengupta.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace seamless {

namespace {

// The nearest hit of one ray so far (remark 1): hits with q > 0 taken,
// best_q the upper bound of the nearest depth (marks beyond it are dropped).
struct Nearest {
    PixelHit best;
    double best_q = std::numeric_limits<double>::infinity();
    void take(int patch, const ParamBox& hb, Interval q, int mark = -1) {
        if (!(q.hi() > 0)) return;
        if (best.patch < 0 || q.mid() < best.q)
            best = {patch, hb.s.mid(), hb.t.mid(), q.mid(), best.candidates, mark};
        best_q = std::min(best_q, q.hi());
    }
};

// One ray's solve: the ray through screen point (a, b), its scene, scratch
// and counters, and its nearest hit so far.
struct RaySolve {
    const ProjectedScene& ps;
    double a, b;
    PixelScratch& scratch;
    RenderStats& st;
    Nearest near;
};

// The covering method of ray_patch.h on a box still undecided.
void cover(RaySolve& r, const ProjectedPatch& pp, const ParamBox& box, int patch) {
    const double a = r.a, b = r.b;
    PixelScratch& scratch = r.scratch;
    RenderStats& st = r.st;
    Nearest& near = r.near;
    scratch.hits.clear();
    RayPatchStats rs;
    intersect(pp.forms, ProjectedScene::primary_ray(a, b), box, scratch.hits, RayPatchOptions{},
              &rs);
    st.hs_iterations += rs.iterations;
    st.hs_steps += rs.iterations;
    if (auto h = nearest_hit(scratch.hits, 0.0)) near.take(patch, h->box, h->q);
}

// A mark's box (or the part of it a clip left): certified Newton; where
// undecided, on the part the Hansen-Sengupta step leaves or its halves (a
// covering method with the cheap test, Jacobians from the ray's power forms),
// and the full covering method only on boxes still undecided at depth 8
// (deeper saved little; 8 keeps the worst case at 256 boxes). J and start: the Jacobian over `box`
// and Newton's start for the first step, when known.
void solve_box(RaySolve& r, const ProjectedPatch& pp, const ParamBox& box0, int patch,
               const MarkJacobian* J = nullptr, const double* start = nullptr) {
    const double a = r.a, b = r.b;
    PixelScratch& scratch = r.scratch;
    RenderStats& st = r.st;
    Nearest& near = r.near;
    RaySystem sys(pp, a, b, scratch.sys, scratch.sys_of);
    ++near.best.candidates;
    ++st.pixel_patch_solves;
    constexpr int kDepth = 8;
    auto& todo = scratch.boxes;
    todo.clear();
    todo.push_back({box0, 0});
    while (!todo.empty()) {
        const auto [popped, depth] = todo.back();
        todo.pop_back();
        CertifiedHit hit;
        const bool first = depth == 0;
        // Below the first box, the shared Jacobian (enclosed over a box
        // holding this one, so over this one too) where it is regular; a
        // fresh one from the ray's power forms only where that step decided
        // nothing and left most of the box.
        const bool shared = J && (first || J->regular);
        // A shared Jacobian that is not regular still proves misses and
        // contracts the box to where the hits may be (Theorem 6 ii and i hold
        // for any enclosure of G'): its step comes before the fresh
        // Jacobian, which is enclosed over the smaller box.
        ParamBox box = popped;
        if (J && !shared && J->preconditioned) {
            if (!may_hold_zero(sys, *J, popped, box, st)) {
                ++st.pixel_newton_certified;
                continue;
            }
        }
        ParamBox rest = box;
        NewtonOutcome nc = newton_certified(sys, box, hit, st, shared ? J : nullptr, &rest,
                                            first ? start : nullptr);
        if (nc == NewtonOutcome::undecided && !first && shared &&
            !(rest.s.width() * rest.t.width() < 0.25 * box.s.width() * box.t.width())) {
            const ParamBox part = rest; // every zero in box is here
            nc = newton_certified(sys, part, hit, st, nullptr, &rest);
        }
        if (nc != NewtonOutcome::undecided) {
            ++st.pixel_newton_certified;
            if (nc == NewtonOutcome::hit) near.take(patch, hit.box, hit.q);
            continue;
        }
        if (depth < kDepth) {
            // The zeros lie in the Hansen-Sengupta step's box: a box it
            // shrank to below half its area is tried again whole, another one
            // is halved (a half took the fewest instructions of the thresholds tried).
            if (rest.s.width() * rest.t.width() < 0.5 * box.s.width() * box.t.width()) {
                todo.push_back({rest, depth + 1});
                continue;
            }
            ParamBox lo = rest, hi = rest;
            if (rest.s.width() >= rest.t.width()) {
                const double m = rest.s.mid();
                lo.s = {rest.s.lo(), m};
                hi.s = {m, rest.s.hi()};
            } else {
                const double m = rest.t.mid();
                lo.t = {rest.t.lo(), m};
                hi.t = {m, rest.t.hi()};
            }
            todo.push_back({hi, depth + 1});
            todo.push_back({lo, depth + 1});
            continue;
        }
        cover(r, pp, box, patch);
    }
}

// Mark k of a small sub-screen: Newton on the mark's whole box first, from
// the previous pixel's hit (where the sub-screen's Jacobian is regular a
// certified hit is the only zero in the box, and the ray needs no clip); else
// the ray's own clip of the mark's subpatch (a certain miss, or a smaller box)
// and solve_box there. (Bezier clipping all the way down, restricting the
// subpatch for the one ray, was tried instead of solve_box: fewer
// Hansen-Sengupta steps, but more instructions for the whole render.)
void solve_shared_mark(RaySolve& r, SharedMarks& shared, size_t k) {
    const double a = r.a, b = r.b;
    PixelScratch& scratch = r.scratch;
    RenderStats& st = r.st;
    Nearest& near = r.near;
    if (shared.refine(k)) {
        // Mark k is now one half, the last mark the other (for the later
        // pixels of B too): this ray is solved on each that it may meet and
        // that is not beyond a hit found already.
        const size_t halves[2] = {k, shared.size() - 1};
        for (const size_t j : halves) {
            const Mark& h = shared.marks()[j];
            if (shared.may_meet_ray(j, a, b) && !(h.hull[2].lo() > near.best_q))
                solve_shared_mark(r, shared, j);
        }
        return;
    }
    const Mark& mark = shared.marks()[k];
    const ProjectedPatch& pp = r.ps.patches[mark.patch];
    const MarkJacobian& J = shared.jacobian(k);
    ParamBox rest = mark.box;
    // After a ray that missed this mark, the miss proof below (the
    // Hansen-Sengupta step over the box) comes before Newton: the same step
    // on the same box as after it, so the outcome is the same either way (a
    // proved miss leaves no hit to certify), without Newton's wasted run
    // beside the patch.
    bool held = false; // the Hansen-Sengupta step over the box ran and left `rest`
    RaySystem sys(pp, a, b, scratch.sys, scratch.sys_of);
    if (shared.missed(k) && J.regular) {
        if (!may_hold_zero(sys, J, mark.box, rest, st, shared.centre(k))) return;
        held = true;
    }
    CertifiedHit hit;
    NewtonFrame at;
    if (newton_hit(sys, mark.box, J, hit, st, {shared.start(k), shared.at_start(k)}, &at)) {
        ++near.best.candidates;
        ++st.pixel_patch_solves;
        ++st.pixel_newton_certified;
        // The next run on k starts at Newton's point, where the certificate's
        // evaluation gave the patch's frame too (the shading's: paint_pixels).
        shared.hit(k, at.s, at.t);
        shared.evaluated(k, at.s, at.t, at.at);
        near.take(mark.patch, hit.box, hit.q, static_cast<int>(k));
        return;
    }
    // Newton left the box (the ray passes beside this part of the patch):
    // with a regular Jacobian one Hansen-Sengupta step over the box mostly
    // proves the miss, at a tenth of the clip's cost.
    if (J.regular && !held && !may_hold_zero(sys, J, mark.box, rest, st, shared.centre(k))) {
        shared.miss(k);
        return;
    }
    // A Jacobian that is not regular still proves a miss where the step's
    // box is empty (Theorem 6 ii holds for any A enclosing G'), and
    // otherwise leaves the part of the box holding every hit (6 i).
    if (!J.regular && J.preconditioned &&
        !may_hold_zero(sys, J, mark.box, rest, st, shared.centre(k))) {
        shared.miss(k);
        return;
    }
    shared.miss(k); // unless solve_box finds a hit below
    ParamBox box;
    // Where the Hansen-Sengupta step shrank the box well (below a quarter),
    // solve_box starts on its box without the clip of the mark's whole
    // subpatch (a quarter took the fewest instructions of the thresholds tried).
    if (rest.s.width() * rest.t.width() < 0.25 * mark.box.s.width() * mark.box.t.width()) {
        box = rest;
    } else {
        if (!clip_box(shared.coefs(), pp.shape, Interval(a), Interval(b), mark, box)) return;
        box = {intersect(box.s, rest.s), intersect(box.t, rest.t)}; // both hold every hit
    }
    if (box.s.is_empty() || box.t.is_empty()) return;
    const PixelHit before = near.best;
    solve_box(r, pp, box, mark.patch, &J, shared.start(k));
    if (near.best.patch == mark.patch &&
        (before.patch != mark.patch || before.s != near.best.s || before.t != near.best.t)) {
        shared.hit(k, near.best.s, near.best.t);
        near.best.mark = static_cast<int>(k);
    }
}

} // namespace

PixelHit solve_pixel(const ProjectedScene& ps, double a, double b, std::span<const Mark> marks,
                     PixelScratch& scratch, RenderStats& st) {
    // Nearest first; once a hit is found, marks that lie entirely beyond it are
    // dropped (section 5, remark 2 after Theorem 10). The ray's q is depth Z.
    scratch.sys_of = {};
    RaySolve r{ps, a, b, scratch, st, {}};
    auto& order = scratch.order;
    order.clear();
    for (size_t k = 0; k < marks.size(); ++k)
        order.push_back({marks[k].hull[2].lo(), static_cast<int>(k)});
    if (order.empty()) return r.near.best;
    std::sort(order.begin(), order.end());
    for (const auto& [zlo, k] : order) {
        if (zlo > r.near.best_q) break;
        // A mark without a subpatch at hand: solve_box on its box.
        const Mark& mark = marks[k];
        solve_box(r, ps.patches[mark.patch], mark.box, mark.patch);
    }
    ++st.primary_rays;
    return r.near.best;
}

PixelHit solve_pixel(const ProjectedScene& ps, double a, double b, SharedMarks& shared,
                     PixelScratch& scratch, RenderStats& st) {
    scratch.sys_of = {};
    RaySolve r{ps, a, b, scratch, st, {}};
    // The marks in the sub-screen's depth order, those the ray may meet:
    // the same sequence as sorting those alone, without a sort per ray.
    // Refines during the walk change only marks already visited (and
    // append halves, which that mark's solve handles).
    for (const auto& [zlo, k] : shared.depth_order()) {
        if (zlo > r.near.best_q) break;
        if (shared.may_meet_ray(k, a, b)) solve_shared_mark(r, shared, k);
    }
    if (r.near.best.candidates > 0) ++st.primary_rays;
    return r.near.best;
}

} // namespace seamless
