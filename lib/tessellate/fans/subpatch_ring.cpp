// SPDX-License-Identifier: MIT
#include <seamless/base/parallel/block_schedule.h>
#include <seamless/base/parallel/cache_line.h>
#include <seamless/base/parallel/huge_pages.h>
#include <seamless/base/parallel/touched_storage.h>
#include <seamless/spline/surface_point.h>
#include <seamless/tessellate/fans/subpatch_ring.h>

#include <algorithm>
#include <span>

namespace seamless {

void RingCollector::collect(int i, const ParamRect& r, std::vector<RingVertex>& ring) {
    const EdgeRegistry& reg = reg_;
    const EdgeGraph& graph = graph_;
    std::vector<int>& scratch = scratch_;
    std::vector<SideVertex>& inside = inside_;
    ring.clear();
    const int cs[4] = {r.s0, r.s1, r.s1, r.s0}, ct[4] = {r.t0, r.t0, r.t1, r.t1};
    for (int k = 0; k < 4; ++k) {
        ring.push_back({cs[k], ct[k], param_of(cs[k]), param_of(ct[k]), -1, -1});
        if (!crack_free_) continue;
        const SideOnLine& side = reg.sides[4 * static_cast<size_t>(i) + k];
        scratch.clear();
        points_inside(reg, side, scratch);
        inside.clear();
        for (int x : scratch) inside.push_back({param_of(x), x, -1});
        if (side.line >= 0 && side.line < reg.boundary_lines) {
            const std::span<const SeamPoint> seam = seam_points(graph, side.line);
            if (!seam.empty()) {
                const double a = param_of(side.a), b = param_of(side.b);
                const size_t before = inside.size();
                for (auto it =
                         std::upper_bound(seam.begin(), seam.end(), a,
                                          [](double x, const SeamPoint&p) { return x < p.x; });
                     it != seam.end() && it->x < b; ++it)
                    inside.push_back({it->x, -1, static_cast<int>(&*it - graph.points.data())});
                if (inside.size() > before && before > 0)
                    std::sort(inside.begin(), inside.end(),
                              [](const SideVertex& p, const SideVertex& q) { return p.x < q.x; });
            }
        }
        if (inside.empty()) continue;
        for (SideVertex& v : inside)
            if (side.reversed) v.x = 1 - v.x, v.grid = kParamOne - v.grid;
        // Sides 0, 1 run with increasing parameter, sides 2, 3 against it.
        if ((k < 2) == side.reversed) std::reverse(inside.begin(), inside.end());
        for (const SideVertex& v : inside) {
            const int g = v.foreign >= 0 ? -1 : v.grid;
            if (k % 2 == 0)
                ring.push_back({g, ct[k], v.x, param_of(ct[k]), v.foreign, -1});
            else
                ring.push_back({cs[k], g, param_of(cs[k]), v.x, v.foreign, -1});
        }
    }
}

SubpatchRings collect_rings(const std::vector<BezierPatch>& patches,
                            const std::vector<Subpatch>& subpatches, const EdgeRegistry& reg,
                            const EdgeGraph& graph, bool crack_free, int threads,
                            const PreviousRings& previous) {
    // Each subpatch's ring and centre point on its own, in parallel; the rings
    // of a block end to end in one array (not one allocation per subpatch).
    const int count = static_cast<int>(subpatches.size());
    // Each on its own cache line (cache_line.h).
    std::vector<OwnLine<std::vector<RingVertex>>> block_rings((count + kSubpatchBlock - 1) /
                                                              kSubpatchBlock);
    SubpatchRings out;
    reserve_touched(out.centre_point, count, threads);
    out.centre_point.resize(count);
    assign_touched(out.start, count + 1, 0, threads);
    reserve_touched(out.centre, count, threads);
    out.centre.resize(count);
    pull_blocks(count, kSubpatchBlock, threads, nullptr, [&](int begin, int end) {
        RingCollector collector(reg, graph, crack_free);
        std::vector<RingVertex> ring;
        std::vector<RingVertex>& block = block_rings[begin / kSubpatchBlock].value;
        for (int i = begin; i < end; ++i) {
            const Subpatch& sp = subpatches[i];
            if (previous.rings && (*previous.same)[sp.patch]) {
                const SubpatchRings& old = *previous.rings;
                const int o =
                    (*previous.previous_start)[sp.patch] + i - (*previous.leaf_start)[sp.patch];
                const auto first = old.vertices.begin() + old.start[o];
                const size_t before = block.size();
                block.insert(block.end(), first, old.vertices.begin() + old.start[o + 1]);
                for (size_t j = before; j < block.size(); ++j) block[j].vertex = -1;
                out.start[i + 1] = old.start[o + 1] - old.start[o];
                out.centre_point[i] = old.centre_point[o];
                continue;
            }
            const ParamRect& r = sp.rect;
            collector.collect(i, r, ring);
            block.insert(block.end(), ring.begin(), ring.end());
            out.start[i + 1] = static_cast<int>(ring.size());
            const double sc = 0.5 * (param_of(r.s0) + param_of(r.s1));
            const double tc = 0.5 * (param_of(r.t0) + param_of(r.t1));
            out.centre_point[i] = exact_point(patches[sp.patch], sc, tc);
        }
    });
    // The blocks laid end to end by a prefix sum.
    for (int i = 0; i < count; ++i) out.start[i + 1] += out.start[i];
    reserve_huge(out.vertices, out.start[count], threads);
    out.vertices.resize(out.start[count]);
    pull_blocks(count, kSubpatchBlock, threads, nullptr, [&](int begin, int) {
        std::vector<RingVertex>& block = block_rings[begin / kSubpatchBlock].value;
        std::copy(block.begin(), block.end(), out.vertices.begin() + out.start[begin]);
        std::vector<RingVertex>().swap(block);
    });
    return out;
}

} // namespace seamless
