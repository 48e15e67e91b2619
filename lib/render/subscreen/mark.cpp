// SPDX-License-Identifier: MIT
#include <seamless/render/subscreen/bezier_clip.h>
#include <seamless/render/subscreen/mark.h>

namespace seamless {
namespace {

const Interval kUnit(0.0, 1.0);

Interval& side(ParamBox& b, int dir) {
    return dir == 0 ? b.s : b.t;
}
Interval side(const ParamBox& b, int dir) {
    return dir == 0 ? b.s : b.t;
}

// Global parameters D.lo + (D.hi - D.lo) u of a local range u, outward.
Interval to_global(Interval D, Interval u) {
    if (u.lo() == 0 && u.hi() == 1) return D;
    const Interval w = Interval(D.hi()) - Interval(D.lo());
    const double lo = (Interval(D.lo()) + w * Interval(u.lo())).lo();
    const double hi = (Interval(D.lo()) + w * Interval(u.hi())).hi();
    return intersect(Interval(lo, hi), D);
}

// The local ends of T within D, as intervals holding the exact ones; false
// when they cannot be enclosed narrowly (a box too thin for its position).
bool to_local(Interval D, Interval T, Interval& u0, Interval& u1) {
    const Interval w = Interval(D.hi()) - Interval(D.lo());
    if (!(w.lo() > 0)) return false;
    u0 = T.lo() == D.lo() ? Interval(0.0)
                          : intersect((Interval(T.lo()) - Interval(D.lo())) / w, kUnit);
    u1 = T.hi() == D.hi() ? Interval(1.0)
                          : intersect((Interval(T.hi()) - Interval(D.lo())) / w, kUnit);
    return !u0.is_empty() && !u1.is_empty() && u0.width() < 1e-6 && u1.width() < 1e-6;
}

// m's subpatch (coefficients c) restricted to `to` (a sub-box of m.box) into
// out; directions whose local ends cannot be enclosed narrowly keep m.box's
// range. Returns the box the new coefficients belong to.
ParamBox restrict_into(const Interval* c, SubpatchShape sh, const Mark& m, ParamBox to,
                       Interval* out) {
    std::copy_n(c, sh.size(), out);
    for (int dir = 0; dir < 2; ++dir) {
        const Interval D = side(m.box, dir), T = side(to, dir);
        if (T.lo() == D.lo() && T.hi() == D.hi()) continue;
        Interval u0, u1;
        if (!to_local(D, T, u0, u1)) {
            side(to, dir) = D;
            continue;
        }
        restrict_subpatch(out, sh, dir, u0, u1);
    }
    return to;
}

// The same appended to the arena (at offset out).
ParamBox restrict_copy(SubpatchArena& arena, SubpatchShape sh, const Mark& m, ParamBox to,
                       size_t& out) {
    out = arena.size();
    arena.resize(out + sh.size());
    return restrict_into(&arena[m.coef], sh, m, to, &arena[out]);
}

double area(const ParamBox& b) {
    return b.s.width() * b.t.width();
}

} // namespace

void update_enclosures(const SubpatchArena& arena, SubpatchShape sh, Mark& m) {
    const Interval* c = &arena[m.coef];
    m.hull = subpatch_hull(c, sh);
    if (!subpatch_projection(c, sh, m.pa, m.pb)) m.pa = m.pb = Interval::entire();
}

Mark whole_patch_mark(int patch, const BezierPatch& b, SubpatchShape sh, const IVec3& hull,
                      SubpatchArena& arena) {
    Mark m{patch, ParamBox{}, hull, arena.size()};
    arena.resize(arena.size() + sh.size());
    control_coefficients(b, sh, &arena[m.coef]);
    update_enclosures(arena, sh, m);
    for (int c = 0; c < 3; ++c) m.hull[c] = intersect(m.hull[c], hull[c]);
    return m;
}

namespace {

// The passes of narrow_mark; `clipped`: the offset of the subpatch of the
// last clip, whose differences are D.
bool narrow_passes(SubpatchArena& arena, SubpatchShape sh, Interval a, Interval b, Mark& m,
                   size_t& clipped) {
    for (int pass = 0; pass < 3; ++pass) {
        Interval u, v;
        clipped = m.coef;
        if (!clip_cluster(&arena[m.coef], sh, a, b, u, v)) return false;
        if (u.lo() == 0 && u.hi() == 1 && v.lo() == 0 && v.hi() == 1) return true;
        // A clip that keeps more than four fifths of the box is not worth a
        // restriction (two de Casteljau passes per row and direction): the
        // mark keeps its box and subpatch, which hold every hit all the same.
        if (u.width() * v.width() > 0.8) return true;
        const double before = area(m.box);
        size_t out;
        const ParamBox got = restrict_copy(
            arena, sh, m, ParamBox{to_global(m.box.s, u), to_global(m.box.t, v)}, out);
        m.box = got;
        m.coef = out;
        if (area(got) > 0.8 * before) return true;
    }
    return true;
}

} // namespace

bool narrow_mark(SubpatchArena& arena, SubpatchShape sh, Interval a, Interval b, Mark& m,
                 IMat<2>* D) {
    size_t clipped = m.coef;
    if (!narrow_passes(arena, sh, a, b, m, clipped)) return false;
    // D of the last clip only (those of earlier passes were overwritten): the
    // subpatch it clipped holds the final box.
    if (D) {
        const Interval* c = &arena[clipped];
        cluster_differences(c, sh, a, b, *D, cluster_lanes_apply(c, sh, a, b));
    }
    return true;
}

bool clip_box(const SubpatchArena& arena, SubpatchShape sh, Interval a, Interval b, const Mark& m,
              ParamBox& box) {
    Interval u, v;
    if (!clip_cluster(&arena[m.coef], sh, a, b, u, v)) return false;
    box = {to_global(m.box.s, u), to_global(m.box.t, v)};
    return true;
}

void bisect_mark(SubpatchArena& arena, SubpatchShape sh, const Mark& m, int dir, Mark out[2]) {
    const Interval D = side(m.box, dir);
    const double mid = D.mid();
    out[0] = out[1] = m;
    ParamBox lo = m.box, hi = m.box;
    side(lo, dir) = Interval(D.lo(), mid);
    side(hi, dir) = Interval(mid, D.hi());
    // Both halves from one de Casteljau triangle where restrict_copy would
    // restrict each at the same local u (its end 0 or 1 thin on the other).
    Interval u0, u;
    if (D.lo() < mid && mid < D.hi() && to_local(D, side(lo, dir), u0, u)) {
        out[0].coef = arena.size();
        out[1].coef = out[0].coef + sh.size();
        arena.resize(out[1].coef + sh.size());
        split_subpatch(&arena[m.coef], sh, dir, u, &arena[out[0].coef], &arena[out[1].coef]);
        out[0].box = lo;
        out[1].box = hi;
        return;
    }
    out[0].box = restrict_copy(arena, sh, m, lo, out[0].coef);
    out[1].box = restrict_copy(arena, sh, m, hi, out[1].coef);
}

int separate_mark(SubpatchArena& arena, SubpatchShape sh, Interval a, Interval b, const Mark& m,
                  Mark out[2]) {
    for (int dir = 0; dir < 2; ++dir) {
        const Interval D = side(m.box, dir);
        if (!(D.width() > 1e-9)) continue;
        const size_t mark_end = arena.size();
        Mark half[2];
        bisect_mark(arena, sh, m, dir, half);
        // The far edge of the lower half is the midline.
        bool apart = false;
        for (int k = 0; k < 2 && !apart; ++k)
            apart = !edge_range(&arena[half[0].coef], sh, a, b, k, dir, true).contains(0.0);
        if (!apart || side(half[0].box, dir).hi() != side(half[1].box, dir).lo()) {
            arena.resize(mark_end);
            continue;
        }
        int n = 0;
        for (Mark& h : half) {
            if (!narrow_mark(arena, sh, a, b, h, nullptr)) continue;
            update_enclosures(arena, sh, h);
            out[n++] = h;
        }
        return n;
    }
    out[0] = m;
    return 1;
}

bool restrict_mark(const SubpatchArena& arena, SubpatchShape sh, const Mark& m, ParamBox to,
                   Interval* out, ParamBox& got) {
    to.s = intersect(to.s, m.box.s);
    to.t = intersect(to.t, m.box.t);
    if (to.s.is_empty() || to.t.is_empty()) return false;
    got = restrict_into(&arena[m.coef], sh, m, to, out);
    return true;
}

bool subpatch_derivatives(const Interval* c, SubpatchShape sh, const ParamBox& box,
                          const IVec3& point, IVec3& ds, IVec3& dt) {
    const Interval ws = Interval(box.s.hi()) - Interval(box.s.lo());
    const Interval wt = Interval(box.t.hi()) - Interval(box.t.lo());
    if (!(ws.lo() > 0) || !(wt.lo() > 0)) return false;
    const Interval p(static_cast<double>(sh.p)), q(static_cast<double>(sh.q));
    // Differences of coordinate d alone: difference_ranges of X_d - 0 Z.
    Interval Xs[4], Xt[4];
    for (int d = 0; d < sh.dim; ++d) {
        Interval du, dv;
        difference_ranges(c, sh, Interval(0.0), d, du, dv, false);
        Xs[d] = p * du / ws;
        Xt[d] = q * dv / wt;
    }
    if (sh.dim == 3) {
        for (int d = 0; d < 3; ++d) {
            ds[d] = Xs[d];
            dt[d] = Xt[d];
        }
        return true;
    }
    Interval W = Interval::empty();
    for (int i = 0; i <= sh.p; ++i)
        for (int j = 0; j <= sh.q; ++j) {
            const Interval w = c[sh.index(3, i, j)];
            if (!(w.lo() > 0)) return false;
            W = hull(W, w);
        }
    for (int d = 0; d < 3; ++d) {
        ds[d] = (Xs[d] - point[d] * Xs[3]) / W;
        dt[d] = (Xt[d] - point[d] * Xt[3]) / W;
    }
    return true;
}

Interval plane_range(const SubpatchArena& arena, SubpatchShape sh, const Mark& m, const Vec3& n) {
    const Interval* c = &arena[m.coef];
    Interval r = Interval::empty();
    for (int i = 0; i <= sh.p; ++i)
        for (int j = 0; j <= sh.q; ++j) {
            Interval v = Interval(n.x) * c[sh.index(0, i, j)] +
                         Interval(n.y) * c[sh.index(1, i, j)] +
                         Interval(n.z) * c[sh.index(2, i, j)];
            if (sh.dim == 4) {
                const Interval w = c[sh.index(3, i, j)];
                if (!(w.lo() > 0)) return Interval::entire();
                v = v / w;
            }
            r = hull(r, v);
        }
    return r;
}

} // namespace seamless
