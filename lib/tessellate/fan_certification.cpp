// SPDX-License-Identifier: MIT
#include <seamless/base/parallel.h>
#include <seamless/tessellate/block_schedule.h>
#include <seamless/tessellate/fan_certification.h>

#include <algorithm>
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

// Subpatch i's fan ring as certified_fan_bound takes it.
void fan_ring(const SubpatchRings& rings, const std::vector<Vec3>& positions, int i,
              std::vector<RingPoint>& fan) {
    fan.clear();
    for (int j = rings.start[i]; j < rings.start[i + 1]; ++j) {
        const RingVertex& v = rings.vertices[j];
        fan.push_back({v.s, v.t, positions[v.vertex], v.fs, v.ft});
    }
}

} // namespace

void certify_fans(const std::vector<BezierPatch>& patches, const SubpatchRings& rings,
                  const std::vector<Vec3>& positions, const std::vector<int>& leaf_start,
                  double scale, double tolerance, int threads, bool keep,
                  std::vector<KnownBounds>& known, std::vector<Subpatch>& subpatches) {
    const int count = static_cast<int>(subpatches.size());
    std::vector<char> fresh(count, 0);
    pull_blocks(count, kSubpatchBlock, threads, nullptr, [&](int begin, int end) {
        std::vector<RingPoint> fan;
        for (int i = begin; i < end; ++i) {
            Subpatch& sp = subpatches[i];
            const Vec3 centre = positions[rings.centre[i]];
            // Certified two-way distance of the subpatch and its fan (error_bound.h).
            fan_ring(rings, positions, i, fan);
            const KnownBounds& k = known[sp.patch];
            const auto it = k.find(subpatch_key(sp.patch, sp.rect));
            if (it != k.end() && it->second.rect == sp.rect && it->second.centre == centre &&
                same_ring(it->second.ring, fan)) {
                sp.error_bound = it->second.bound;
            } else {
                sp.error_bound = certified_fan_bound(patches[sp.patch], sp.rect, sp.depth, centre,
                                                     fan, scale, tolerance);
                fresh[i] = 1;
            }
        }
    });
    // The fresh bounds kept for the next pass: each patch's map on its own.
    const int np = static_cast<int>(patches.size());
    parallel_chunks(keep ? np : 0, threads, [&](int begin, int end) {
        for (int p = begin; p < end; ++p)
            for (int i = leaf_start[p]; i < leaf_start[p + 1]; ++i) {
                if (!fresh[i]) continue;
                const Subpatch& sp = subpatches[i];
                KnownBound& k = known[p][subpatch_key(sp.patch, sp.rect)];
                fan_ring(rings, positions, i, k.ring);
                k.rect = sp.rect;
                k.centre = positions[rings.centre[i]];
                k.bound = sp.error_bound;
            }
    });
}

} // namespace seamless
