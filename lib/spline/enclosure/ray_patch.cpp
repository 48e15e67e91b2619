// SPDX-License-Identifier: MIT
#include <seamless/spline/enclosure/ray_patch.h>

#include <seamless/base/check.h>
#include <seamless/interval/hansen_sengupta.h>

#include <array>
#include <cmath>

namespace seamless {
namespace {

// F and its partial derivatives for one ray.
struct RaySystem {
    PowerForm F, Fs, Ft;
};

void ray_system(const PatchForms& patch, const Ray& ray, RaySystem& sys) {
    const Vec3 D = ray.direction;
    // e_1, e_2 EXACTLY orthogonal to D: with k the largest component of D,
    // e = D_k u_j - D_j u_k has e . D = D_k D_j - D_j D_k = 0 in floating point too,
    // so the certified line is the ray itself, not a rounded neighbour.
    int k = 0;
    for (int c = 1; c < 3; ++c)
        if (std::abs(D[c]) > std::abs(D[k])) k = c;
    Vec3 e[2];
    for (int r = 0, j = 0; j < 3; ++j) {
        if (j == k) continue;
        Vec3 v{};
        v[j] = D[k];
        v[k] = -D[j];
        e[r++] = v;
    }
    Interval m[2][PowerForm::kMaxDim];
    for (int r = 0; r < 2; ++r) {
        Interval eo(0.0);
        for (int c = 0; c < 3; ++c) {
            m[r][c] = Interval(e[r][c]);
            eo += Interval(e[r][c]) * Interval(ray.origin[c]);
        }
        m[r][3] = -eo; // e . X - (e . O) W
    }
    combine(patch.X, m, 2, sys.F);
    derivative_s(sys.F, sys.Fs);
    derivative_t(sys.F, sys.Ft);
}

IVec<2> to_ivec(ParamBox b) {
    return IVec<2>{{b.s, b.t}};
}
ParamBox to_box(const IVec<2>& x) {
    return {x[0], x[1]};
}

enum class Outcome { none, hit, bisect };

struct Refined {
    Outcome outcome = Outcome::none;
    IVec<2> box;
    bool unique = false;
};

// Hansen-Sengupta iteration on one box (section 7 remark 1).
Refined refine(const RaySystem& sys, IVec<2> x, bool unique, const RayPatchOptions& opt,
               RayPatchStats& st) {
    for (int it = 0; it < opt.max_iterations; ++it) {
        const ParamBox box = to_box(x);
        // Cheap exclusion: 0 must lie in the enclosure of both F_k over the box.
        for (int r = 0; r < 2; ++r)
            if (!enclose(sys.F, sys.Fs, sys.Ft, r, box).contains(0.0)) return {};
        IMat<2> A; // Lipschitz matrix F'(x) (Definition 4)
        for (int r = 0; r < 2; ++r) {
            A(r, 0) = horner(sys.Fs, r, box);
            A(r, 1) = horner(sys.Ft, r, box);
        }
        const RVec<2> c = mid(x);
        IVec<2> fc;
        for (int r = 0; r < 2; ++r) fc[r] = evaluate(sys.F, r, c[0], c[1]);
        const HansenSenguptaStep<2> step = hansen_sengupta(A, fc, x, c);
        ++st.iterations;
        if (step.box.is_empty()) return {}; // Theorem 6 ii: no zero in x
        // Theorem 6 iii: one zero in x; the new box holds every zero of x, so
        // the certificate carries over to all later (smaller) boxes.
        unique = unique || step.unique;
        const double w_old = max_width(x), w_new = max_width(step.box);
        x = step.box;
        if (unique && w_new <= opt.tolerance) return {Outcome::hit, x, true};
        if (!(w_new < opt.min_contraction * w_old)) { // no progress
            if (w_new <= opt.tolerance) return {Outcome::hit, x, unique};
            // A certified box keeps contracting (Theorem 7) while it shrinks at all.
            if (unique && w_new < w_old) continue;
            return {Outcome::bisect, x, false}; // halves must certify afresh
        }
    }
    if (unique || max_width(x) <= opt.tolerance) return {Outcome::hit, x, unique};
    return {Outcome::bisect, x, false};
}

Interval ray_parameter(const PatchForms& patch, const Ray& ray, ParamBox box) {
    const IVec3 P = enclose_point(patch, box);
    Interval num(0.0), den(0.0);
    for (int c = 0; c < 3; ++c) {
        const Interval d(ray.direction[c]);
        num += (P[c] - Interval(ray.origin[c])) * d;
        den += d * d;
    }
    return num / den;
}

ParamBox clip_to(ParamBox outer, ParamBox b) {
    return {intersect(b.s, outer.s), intersect(b.t, outer.t)};
}
ParamBox clip_to_unit(ParamBox b) {
    return clip_to(ParamBox{}, b);
}

// Covering method (section 5 remark 2): the boxes of start that refine()
// cannot exclude, each a hit (certified or not) once it is narrow enough or
// out of depth or budget, appended to hits.
void cover(const RaySystem& sys, ParamBox start, std::vector<RayPatchHit>& hits,
           const RayPatchOptions& options, RayPatchStats& st) {
    struct Entry {
        IVec<2> box;
        int depth;
    };
    // Depth-first: the stack never holds more than one box per level plus one.
    std::array<Entry, kMaxRayPatchDepth + 2> stack;
    int top = 0;
    stack[top++] = {to_ivec(start), 0};
    long long budget = options.max_boxes;
    while (top > 0) {
        const Entry e = stack[--top];
        ++st.boxes;
        if (--budget < 0) { // out of budget: report the box as it is
            ++st.unresolved;
            hits.push_back({to_box(e.box), {}, false});
            continue;
        }
        const Refined r = refine(sys, e.box, false, options, st);
        if (r.outcome == Outcome::none) continue;
        if (r.outcome == Outcome::hit) {
            if (!r.unique) ++st.unresolved;
            hits.push_back({to_box(r.box), {}, r.unique});
            continue;
        }
        if (e.depth >= options.max_depth) {
            ++st.unresolved;
            hits.push_back({to_box(r.box), {}, false});
            continue;
        }
        // Bisect the wider parameter interval.
        ++st.bisections;
        const int d = r.box[0].width() >= r.box[1].width() ? 0 : 1;
        const double m = r.box[d].mid();
        IVec<2> lo = r.box, hi = r.box;
        lo[d] = {r.box[d].lo(), m};
        hi[d] = {m, r.box[d].hi()};
        stack[top++] = {hi, e.depth + 1};
        stack[top++] = {lo, e.depth + 1};
    }
}

// A zero on a bisection line, or one that rounding keeps from being excluded
// next to a certified box, leaves several touching boxes: merged here (hits
// from index first on), each merged box uncertified.
void merge_touching(std::vector<RayPatchHit>& hits, size_t first) {
    for (size_t i = first; i < hits.size(); ++i)
        for (size_t j = i + 1; j < hits.size(); ++j) {
            if (!hits[i].box.s.overlaps(hits[j].box.s) || !hits[i].box.t.overlaps(hits[j].box.t))
                continue;
            hits[i].box = {hull(hits[i].box.s, hits[j].box.s), hull(hits[i].box.t, hits[j].box.t)};
            hits[i].unique = false;
            hits[j] = hits.back();
            hits.pop_back();
            j = i; // rescan against the grown box
        }
}

// An uncertified hit certified after epsilon inflation within the start box
// (zeros outside it are not asked for), if refine() certifies the inflated box.
void certify_inflated(const RaySystem& sys, ParamBox start, RayPatchHit& h,
                      const RayPatchOptions& options, RayPatchStats& st) {
    if (h.unique) return;
    const double eps = std::max(max_width(to_ivec(h.box)), options.tolerance);
    const ParamBox inflated = clip_to(start, {Interval(h.box.s.lo() - eps, h.box.s.hi() + eps),
                                              Interval(h.box.t.lo() - eps, h.box.t.hi() + eps)});
    const Refined r = refine(sys, to_ivec(inflated), false, options, st);
    if (r.outcome == Outcome::hit && r.unique) {
        h.box = to_box(r.box);
        h.unique = true;
    }
}

} // namespace

void intersect(const PatchForms& patch, const Ray& ray, std::vector<RayPatchHit>& hits,
               const RayPatchOptions& options, RayPatchStats* stats) {
    intersect(patch, ray, ParamBox{}, hits, options, stats);
}

void intersect(const PatchForms& patch, const Ray& ray, ParamBox start,
               std::vector<RayPatchHit>& hits, const RayPatchOptions& options,
               RayPatchStats* stats) {
    SEAMLESS_CHECK(options.max_depth >= 0 && options.max_depth <= kMaxRayPatchDepth,
                   "the covering stack holds kMaxRayPatchDepth levels");
    SEAMLESS_CHECK(dot(ray.direction, ray.direction) > 0, "a ray has a direction");
    RayPatchStats local;
    RayPatchStats& st = stats ? *stats : local;
    RaySystem sys; // its coefficients unset until ray_system writes them (power_form.h)
    ray_system(patch, ray, sys);
    const size_t first = hits.size();
    start = clip_to_unit(start);
    if (start.s.is_empty() || start.t.is_empty()) return;
    cover(sys, start, hits, options, st);
    merge_touching(hits, first);
    for (size_t i = first; i < hits.size(); ++i) {
        certify_inflated(sys, start, hits[i], options, st);
        hits[i].q = ray_parameter(patch, ray, hits[i].box);
    }
}

std::vector<RayPatchHit> intersect(const PatchForms& patch, const Ray& ray,
                                   const RayPatchOptions& options, RayPatchStats* stats) {
    std::vector<RayPatchHit> hits;
    intersect(patch, ray, hits, options, stats);
    return hits;
}

std::optional<RayPatchHit> nearest_hit(const std::vector<RayPatchHit>& hits, double q_min) {
    std::optional<RayPatchHit> best;
    for (const RayPatchHit& h : hits) {
        if (h.q.is_empty() || h.q.hi() < q_min) continue;
        if (!best || h.q.lo() < best->q.lo()) best = h;
    }
    return best;
}

std::optional<RayPatchHit> nearest_hit(const PatchForms& patch, const Ray& ray,
                                       const RayPatchOptions& options, RayPatchStats* stats,
                                       double q_min) {
    return nearest_hit(intersect(patch, ray, options, stats), q_min);
}

} // namespace seamless
