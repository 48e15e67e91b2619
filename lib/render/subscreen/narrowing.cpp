// SPDX-License-Identifier: MIT
// INTRACY step 3 (narrowing.h).
#include <seamless/render/subscreen/narrowing.h>

#include <seamless/render/scene/step_clock.h>

#include <algorithm>
#include <optional>

namespace seamless {

void MarkNarrowing::narrow(MarkStack& stack, const SubScreen& B, RenderStats& st) {
    std::vector<Mark>& arena = stack.marks;
    SubpatchArena& coefs = stack.coefs;
    const bool thin = B.thin();
    const Interval a = screen_a(ps_.frame, B.x0, B.x1), b = screen_b(ps_.frame, B.y0, B.y1);
    const double pitch_a = 2.0 * ps_.frame.tan_half * ps_.frame.aspect / ps_.frame.width;
    const double pitch_b = 2.0 * ps_.frame.tan_half / ps_.frame.height;
    std::optional<StepClock> narrowing;
    if (!thin) narrowing.emplace(st.narrow_seconds);
    for (size_t k = B.offset; k < B.offset + B.count; ++k) {
        // Covering method (section 5, remark 2 after Theorem 10): where Theorem 10
        // cannot narrow a box (near a silhouette) and the box still projects far
        // beyond B, it is bisected and both halves go on.
        work_.clear();
        work_.push_back(arena[k]);
        int budget = kMaxBisections;
        while (!work_.empty()) {
            Mark m = work_.back();
            work_.pop_back();
            // Hull comparison with the enclosures the mark brought from its parent.
            if (!may_meet(m, a, b)) continue;
            if (thin) {
                arena.push_back(m);
                continue;
            }
            const SubpatchShape sh = ps_.patches[m.patch].shape;
            ++st.marks_narrowed;
            IMat<2> A;
            if (!narrow_mark(coefs, sh, a, b, m, &A)) continue;
            update_enclosures(coefs, sh, m);
            const IVec3& Q = m.hull;
            const Interval pa = m.pa.is_finite() ? m.pa : Q[0] / Q[2];
            const Interval pb = m.pb.is_finite() ? m.pb : Q[1] / Q[2];
            const bool wide = !(Q[2].lo() > 0) || pa.width() > 2 * (a.width() + pitch_a) ||
                              pb.width() > 2 * (b.width() + pitch_b);
            if (wide && budget > 0 && std::max(m.box.s.width(), m.box.t.width()) > 1e-9) {
                --budget;
                ++st.mark_bisections;
                Mark half[2];
                bisect_mark(coefs, sh, m, m.box.s.width() >= m.box.t.width() ? 0 : 1, half);
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
                J.contains(0.0) ? separate_mark(coefs, sh, a, b, m, parts) : (parts[0] = m, 1);
            for (int i = 0; i < n; ++i) arena.push_back(parts[i]);
        }
    }
}

} // namespace seamless
