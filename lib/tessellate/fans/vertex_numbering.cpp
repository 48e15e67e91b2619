// SPDX-License-Identifier: MIT
#include <seamless/base/first_met.h>
#include <seamless/base/parallel/block_schedule.h>
#include <seamless/base/parallel/cache_line.h>
#include <seamless/base/parallel/touched_storage.h>
#include <seamless/tessellate/fans/vertex_numbering.h>

#include <algorithm>
#include <cstdint>
#include <numeric>

namespace seamless {
namespace {

// A vertex on a straight segment places the segment's ends first: one by one.
void number_one_by_one(const std::vector<Subpatch>& subpatches, const EdgeGraph& graph,
                       VertexRegistry& vr, SubpatchRings& rings) {
    const size_t count = subpatches.size();
    // About three vertices per subpatch: reserving avoids the copies of
    // growing these arrays.
    vr.positions.reserve(3 * count);
    vr.placed.reserve(3 * count);
    vr.index.reserve(2 * count);
    for (size_t i = 0; i < count; ++i) {
        const Subpatch& sp = subpatches[i];
        for (int j = rings.start[i]; j < rings.start[i + 1]; ++j) {
            RingVertex& v = rings.vertices[j];
            v.vertex = v.foreign >= 0 ? vertex_of(vr, graph.points[v.foreign].key)
                                      : vertex_at(vr, sp.patch, v.s, v.t);
        }
        rings.centre[i] = static_cast<int>(vr.positions.size());
        vr.positions.push_back(rings.centre_point[i]);
        vr.placed.push_back(1);
    }
}

// Vertices numbered as first met in subpatch order, each ring then its
// centre, as vertex_of numbers them one by one, where every vertex is its
// exact point (no straight segments: no vertex places another). In parallel:
// the keys; the first uses of each patch's interior points (they belong to
// that patch alone, and its subpatches are consecutive); the ids by a prefix
// sum over the subpatches' new vertices; the positions. In one pass: the first
// uses of the patch-boundary points, a small share of the slots.
void number_in_parallel(const std::vector<Subpatch>& subpatches, const std::vector<int>& leaf_start,
                        const EdgeGraph& graph, int threads, VertexRegistry& vr,
                        SubpatchRings& rings, const PreviousRings& previous) {
    const int count = static_cast<int>(subpatches.size());
    const int np = static_cast<int>(leaf_start.size()) - 1;
    const std::vector<int>& ring_start = rings.start;
    std::vector<RingVertex>& ring = rings.vertices;
    std::vector<VertexKey>& key = rings.keys;
    reserve_touched(key, ring.size(), threads);
    key.resize(ring.size());
    std::vector<int> first; // the slot of the key's first use
    reserve_touched(first, ring.size(), threads);
    first.resize(ring.size());
    // A ring copied from the previous pass has its keys (the same slots and,
    // without seam vertices or aliases, the same keys): copied too (teapot
    // D = 0.001, second pass: 30 of 32 patches).
    const bool old_keys =
        previous.positions && previous.rings->keys.size() == previous.rings->vertices.size();
    pull_blocks(count, kSubpatchBlock, threads, nullptr, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) {
            const int p = subpatches[i].patch;
            if (old_keys && (*previous.same)[p]) {
                const SubpatchRings& old = *previous.rings;
                const int o = (*previous.previous_start)[p] + i - leaf_start[p];
                std::copy(old.keys.begin() + old.start[o], old.keys.begin() + old.start[o + 1],
                          key.begin() + ring_start[i]);
                continue;
            }
            for (int j = ring_start[i]; j < ring_start[i + 1]; ++j) {
                const RingVertex& v = ring[j];
                key[j] = canonical_key(
                    vr, v.foreign >= 0 ? graph.points[v.foreign].key
                                       : vertex_key(*vr.match, subpatches[i].patch, v.s, v.t));
            }
        }
    });
    const auto interior = [&](int j, int patch) { return key[j].kind == 2 && key[j].id == patch; };
    // Patches differ in slots by ten times and more (teapot): largest first.
    std::vector<int> order(np);
    std::iota(order.begin(), order.end(), 0);
    const auto slots = [&](int p) {
        return ring_start[leaf_start[p + 1]] - ring_start[leaf_start[p]];
    };
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return slots(a) > slots(b); });
    // Each patch's slots of shared points (keys not interior to it), in slot
    // order: found here rather than by a scan of every slot on the calling
    // thread (teapot D = 0.001: 90,000 slots a pass).
    std::vector<OwnLine<std::vector<int>>> shared_of(np); // cache_line.h
    pull_blocks(np, 1, threads, &order, [&](int begin, int end) {
        FirstMet<std::uint64_t, MixHash> seen; // (s, t) -> first slot
        std::vector<int> first_of;             // previous vertex number -> first slot
        for (int p = begin; p < end; ++p) {
            const int j0 = ring_start[leaf_start[p]], j1 = ring_start[leaf_start[p + 1]];
            std::vector<int>& shared_slots = shared_of[p].value;
            const int o = previous.positions ? (*previous.previous_start)[p] : 0;
            const int n = leaf_start[p + 1] - leaf_start[p];
            if (previous.positions && (*previous.same)[p] && n > 0) {
                // The previous pass numbered the same rings: one number per
                // key, and the patch's interior points were numbered in its
                // own subpatches, after the centre of the subpatch before.
                const SubpatchRings& old = *previous.rings;
                const int lo = o == 0 ? 0 : old.centre[o - 1] + 1;
                first_of.assign(old.centre[o + n - 1] + 1 - lo, -1);
                const RingVertex* old_ring = old.vertices.data() + old.start[o] - j0;
                for (int j = j0; j < j1; ++j) {
                    if (!interior(j, p)) {
                        shared_slots.push_back(j);
                        continue;
                    }
                    int& f = first_of[old_ring[j].vertex - lo];
                    if (f < 0) f = j;
                    first[j] = f;
                }
                continue;
            }
            seen.reset(j1 - j0);
            for (int j = j0; j < j1; ++j) {
                if (!interior(j, p)) {
                    shared_slots.push_back(j);
                    continue;
                }
                const std::uint64_t st = (static_cast<std::uint64_t>(key[j].a) << 32) |
                                         static_cast<std::uint32_t>(key[j].b);
                first[j] = seen.emplace(st, j);
            }
        }
    });
    size_t shared_count = 0;
    for (const auto& slots_of_p : shared_of) shared_count += slots_of_p.value.size();
    FirstMet<VertexKey, VertexKeyHash> shared;
    shared.reset(shared_count);
    for (const auto& slots_of_p : shared_of)
        for (int j : slots_of_p.value) first[j] = shared.emplace(key[j], j);
    std::vector<int> base(count + 1, 0);
    pull_blocks(count, kSubpatchBlock, threads, nullptr, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) {
            int fresh = 1; // the centre
            for (int j = ring_start[i]; j < ring_start[i + 1]; ++j) fresh += first[j] == j;
            base[i + 1] = fresh;
        }
    });
    for (int i = 0; i < count; ++i) base[i + 1] += base[i];
    reserve_touched(vr.positions, base[count], threads);
    vr.positions.resize(base[count]);
    vr.placed.assign(base[count], 1);
    pull_blocks(count, kSubpatchBlock, threads, nullptr, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) {
            int id = base[i];
            const int p = subpatches[i].patch;
            if (previous.positions && (*previous.same)[p]) {
                // The same ring, slot by slot, and the same keys.
                const SubpatchRings& old = *previous.rings;
                const int o = (*previous.previous_start)[p] + i - leaf_start[p];
                const RingVertex* old_ring = old.vertices.data() + old.start[o] - ring_start[i];
                for (int j = ring_start[i]; j < ring_start[i + 1]; ++j)
                    if (first[j] == j) {
                        ring[j].vertex = id;
                        vr.positions[id++] = (*previous.positions)[old_ring[j].vertex];
                    }
            } else {
                for (int j = ring_start[i]; j < ring_start[i + 1]; ++j)
                    if (first[j] == j) {
                        ring[j].vertex = id;
                        vr.positions[id++] = exact_position(*vr.patches, *vr.match, key[j]);
                    }
            }
            rings.centre[i] = id;
            vr.positions[id] = rings.centre_point[i];
        }
    });
    pull_blocks(count, kSubpatchBlock, threads, nullptr, [&](int begin, int end) {
        for (int i = begin; i < end; ++i)
            for (int j = ring_start[i]; j < ring_start[i + 1]; ++j)
                if (first[j] != j) ring[j].vertex = ring[first[j]].vertex;
    });
}

} // namespace

void number_vertices(const std::vector<Subpatch>& subpatches, const std::vector<int>& leaf_start,
                     const EdgeGraph& graph, int threads, VertexRegistry& vr, SubpatchRings& rings,
                     const PreviousRings& previous) {
    if (vr.crack_free && vr.straight_segments)
        number_one_by_one(subpatches, graph, vr, rings);
    else
        number_in_parallel(subpatches, leaf_start, graph, threads, vr, rings, previous);
}

} // namespace seamless
