// SPDX-License-Identifier: MIT
#include <seamless/base/parallel/block_schedule.h>
#include <seamless/base/parallel/parallel.h>
#include <seamless/tessellate/bounds/fan_certification.h>
#include <seamless/tessellate/pass_progress.h>

#include <algorithm>
#include <atomic>
#include <numeric>
#include <span>

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
                continue;
            }
            const Vec3 centre = positions[rings.centre[i]];
            // Certified two-way distance of the subpatch and its fan (error_bound.h).
            fan.clear();
            fan_ring(rings, positions, i, fan);
            if (b && b->rect == sp.rect && b->centre == centre &&
                same_ring(std::span(k.rings).subspan(b->ring_first, b->ring_size), fan)) {
                sp.error_bound = b->bound;
            } else {
                sp.error_bound = certified_fan_bound(patches_[sp.patch], sp.rect, sp.depth, centre,
                                                     fan, scale_, tolerance_);
                fresh[i] = 1;
            }
        }
        if (progress && *progress)
            progress->within(PassProgress::kNumbered, PassProgress::kBounded,
                             done.fetch_add(end - begin) + (end - begin), count);
    });
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
        }
    });
}

} // namespace seamless
