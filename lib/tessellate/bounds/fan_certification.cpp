// SPDX-License-Identifier: MIT
#include <seamless/base/parallel/block_schedule.h>
#include <seamless/base/parallel/parallel.h>
#include <seamless/spline/surface_point.h>
#include <seamless/tessellate/bounds/fan_certification.h>
#include <seamless/tessellate/pass_progress.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <numeric>
#include <span>
#include <utility>

namespace seamless {
namespace {

bool same_ring(std::span<const RingPoint> a, std::span<const RingPoint> b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                      [](const RingPoint& p, const RingPoint& q) {
                          return p.s == q.s && p.t == q.t && p.fs == q.fs && p.ft == q.ft &&
                                 p.position == q.position;
                      });
}

// Subpatch i's fan ring as certified_fan_bound takes it, appended to `fan`.
void fan_ring(const SubpatchRings& rings, const std::vector<Vec3>& positions, int i,
              std::vector<RingPoint>& fan) {
    for (int j = rings.start[i]; j < rings.start[i + 1]; ++j) {
        const RingVertex& v = rings.vertices[j];
        fan.push_back({v.s, v.t, positions[v.vertex], v.fs, v.ft});
    }
}

// The most a quad's triangle may turn from the surface's normal at the
// subpatch's centre where the angle is not checked at its corners (radians,
// 45 degrees).
constexpr double kQuadTurn = 0.7853981633974483;

// Subpatch sp's ring of four distinct corners (counterclockwise from
// (s0, t0)) as two triangles: the fan from the midpoint of a diagonal over
// the corners is those two triangles as a point set, so its certified bound
// (error_bound.h: the construction never asks the centre to lie on the
// surface) is theirs. The diagonal whose midpoint lies nearer the surface's
// centre point is tried, at the coarsest refinement only (most trials that
// fail, fail there). Accepted within the tolerance and with the triangles'
// normals near the surface's (below: with an angle, neighbouring triangles
// then differ by at most it, as fan_accepted's fans, subdivision.cpp).
struct QuadVerdict {
    signed char diagonal = -1;
    double bound = 0;
};

QuadVerdict quad_verdict(const BezierPatch& b, const Subpatch& sp, Vec3 centre,
                         std::span<const RingPoint> ring, double scale, double tolerance,
                         double angle) {
    if (ring.size() != 4) return {};
    for (size_t k = 0; k < 4; ++k)
        for (size_t j = k + 1; j < 4; ++j)
            if (ring[k].position == ring[j].position) return {};
    const Vec3 m02 = 0.5 * (ring[0].position + ring[2].position);
    const Vec3 m13 = 0.5 * (ring[1].position + ring[3].position);
    const int d = distance(m02, centre) <= distance(m13, centre) ? 0 : 1;
    // Each triangle's normal within angle / 2 of the regular normals at its
    // corners and the centre (a fan within kTinyFan of the tolerance, as
    // fan_accepted's, by the centre's alone and within 45 degrees:
    // a triangle across a fold, where two surfaces meet at a tiny tip, would
    // lie on the other side's triangle).
    double reach = 0;
    for (const RingPoint& p : ring) reach = std::max(reach, distance(p.position, centre));
    const bool corners = angle > 0 && reach > kTinyFan * tolerance;
    const double turn = angle > 0 ? 0.5 * angle : kQuadTurn;
    const double cos_half = std::cos(corners ? turn : std::min(turn, kQuadTurn));
    const auto param = [](const RingPoint& p, bool u) {
        const double f = u ? p.fs : p.ft;
        return f >= 0 ? f : param_of(u ? p.s : p.t);
    };
    const double sc = 0.5 * (param_of(sp.rect.s0) + param_of(sp.rect.s1));
    const double tc = 0.5 * (param_of(sp.rect.t0) + param_of(sp.rect.t1));
    Vec3 centre_normal;
    if (!regular_unit_normal(b, sc, tc, centre_normal)) return {};
    for (int half = 0; half < 2; ++half) {
        const int k0 = d, k1 = d + 1 + half, k2 = (d + 2 + half) % 4;
        const Vec3 m =
            cross(ring[k1].position - ring[k0].position, ring[k2].position - ring[k0].position);
        if (!(norm(m) > 0)) return {};
        const Vec3 n = normalize(m);
        if (dot(centre_normal, n) < cos_half) return {};
        Vec3 sn;
        for (int k : {k0, k1, k2})
            if (corners &&
                regular_unit_normal(b, param(ring[k], true), param(ring[k], false), sn) &&
                dot(sn, n) < cos_half)
                return {};
    }
    const double bound = certified_fan_bound(b, sp.rect, sp.depth, d == 0 ? m02 : m13, ring, scale,
                                             tolerance, false);
    if (!(bound <= tolerance)) return {};
    return {static_cast<signed char>(d), bound};
}

} // namespace

std::vector<char> FanCertification::certify(const SubpatchRings& rings,
                                            const std::vector<Vec3>& positions,
                                            const std::vector<char>* same,
                                            std::vector<Subpatch>& subpatches,
                                            const PassProgress* progress) const {
    const int count = static_cast<int>(subpatches.size());
    std::vector<char> fresh(count, 0);
    std::atomic<int> done{0};
    pull_blocks(count, kSubpatchBlock, threads_, nullptr, [&](int begin, int end) {
        std::vector<RingPoint> fan;
        for (int i = begin; i < end; ++i) {
            Subpatch& sp = subpatches[i];
            const KnownBounds& k = known_[sp.patch];
            const KnownBound* b = k.bounds.find(subpatch_key(sp.patch, sp.rect));
            // A patch left as it was: its rings are not built and compared
            // again (most patches in a later pass).
            if (same && (*same)[sp.patch] && b && b->rect == sp.rect) {
                sp.error_bound = b->bound;
                sp.diagonal = b->diagonal;
                continue;
            }
            const Vec3 centre = positions[rings.centre[i]];
            // Certified two-way distance of the subpatch and its fan (error_bound.h).
            fan.clear();
            fan_ring(rings, positions, i, fan);
            if (b && b->rect == sp.rect && b->centre == centre &&
                same_ring(std::span(k.rings).subspan(b->ring_first, b->ring_size), fan)) {
                sp.error_bound = b->bound;
                sp.diagonal = b->diagonal;
            } else {
                const BezierPatch& patch = patches_[sp.patch];
                const QuadVerdict q = tolerance_ > 0 ? quad_verdict(patch, sp, centre, fan, scale_,
                                                                    tolerance_, angle_)
                                                     : QuadVerdict{};
                sp.diagonal = q.diagonal;
                sp.error_bound = q.diagonal >= 0
                                     ? q.bound
                                     : certified_fan_bound(patch, sp.rect, sp.depth, centre, fan,
                                                           scale_, tolerance_);
                fresh[i] = 1;
            }
        }
        if (progress && *progress)
            progress->within(PassProgress::kNumbered, PassProgress::kBounded,
                             done.fetch_add(end - begin) + (end - begin), count);
    });
    // Two quads' triangles on the same three vertices (surfaces that coincide
    // near a tip, a fin of no thickness) would be one triangle twice: both
    // subpatches keep their fans, whose centres differ.
    std::vector<std::pair<std::array<int, 3>, int>> quads;
    for (int i = 0; i < count; ++i) {
        const signed char d = subpatches[i].diagonal;
        if (d < 0) continue;
        const RingVertex* v = &rings.vertices[rings.start[i]];
        for (int half = 0; half < 2; ++half) {
            std::array<int, 3> t{v[d].vertex, v[d + 1 + half].vertex, v[(d + 2 + half) % 4].vertex};
            std::sort(t.begin(), t.end());
            quads.push_back({t, i});
        }
    }
    std::sort(quads.begin(), quads.end());
    for (size_t q = 1; q < quads.size(); ++q) {
        if (quads[q].first != quads[q - 1].first) continue;
        for (int i : {quads[q - 1].second, quads[q].second}) {
            Subpatch& sp = subpatches[i];
            if (sp.diagonal < 0) continue;
            std::vector<RingPoint> fan;
            fan_ring(rings, positions, i, fan);
            sp.diagonal = -1;
            sp.error_bound =
                certified_fan_bound(patches_[sp.patch], sp.rect, sp.depth,
                                    positions[rings.centre[i]], fan, scale_, tolerance_);
            fresh[i] = 1;
        }
    }
    return fresh;
}

void FanCertification::keep(const SubpatchRings& rings, const std::vector<Vec3>& positions,
                            const std::vector<int>& leaf_start, const std::vector<char>& fresh,
                            const std::vector<char>* compared,
                            const std::vector<Subpatch>& subpatches) {
    const int np = static_cast<int>(leaf_start.size()) - 1;
    // Patches differ in subpatches by ten times and more (teapot): largest
    // first. Each patch's table and rings sized once for what it adds.
    std::vector<int> order(np);
    std::iota(order.begin(), order.end(), 0);
    const auto size = [&](int p) { return leaf_start[p + 1] - leaf_start[p]; };
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return size(a) > size(b); });
    pull_blocks(np, 1, threads_, &order, [&](int p, int) {
        const bool with_rings = !compared || (*compared)[p];
        std::size_t added = 0, slots = 0;
        for (int i = leaf_start[p]; i < leaf_start[p + 1]; ++i)
            if (fresh[i]) ++added, slots += rings.start[i + 1] - rings.start[i];
        std::vector<RingPoint>& kept = known_[p].rings;
        known_[p].bounds.reserve(known_[p].bounds.size() + added);
        if (with_rings) kept.reserve(kept.size() + slots);
        for (int i = leaf_start[p]; i < leaf_start[p + 1]; ++i) {
            if (!fresh[i]) continue;
            const Subpatch& sp = subpatches[i];
            KnownBound& k = known_[p].bounds[subpatch_key(sp.patch, sp.rect)];
            k.ring_first = static_cast<int>(kept.size());
            if (with_rings) fan_ring(rings, positions, i, kept);
            k.ring_size = static_cast<int>(kept.size()) - k.ring_first;
            k.rect = sp.rect;
            k.centre = positions[rings.centre[i]];
            k.bound = sp.error_bound;
            k.diagonal = sp.diagonal;
        }
    });
}

} // namespace seamless
