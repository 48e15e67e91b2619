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
class ParallelNumbering {
  public:
    ParallelNumbering(const std::vector<Subpatch>& subpatches, const std::vector<int>& leaf_start,
                      const EdgeGraph& graph, int threads, VertexRegistry& vr, SubpatchRings& rings,
                      const PreviousRings& previous)
        : subpatches_(subpatches), leaf_start_(leaf_start), graph_(graph), threads_(threads),
          vr_(vr), rings_(rings), previous_(previous), count_(static_cast<int>(subpatches.size())),
          np_(static_cast<int>(leaf_start.size()) - 1) {}

    // Every ring slot's canonical key.
    void keys();
    // Every slot's first use of its key: per patch its interior points, then
    // the shared points in slot order.
    void first_uses();
    // The ids: each subpatch's new vertices from base[i] on, then its centre;
    // their positions.
    void number();

  private:
    bool interior(int j, int patch) const {
        const VertexKey& k = rings_.keys[j];
        return k.kind == 2 && k.id == patch;
    }
    // Patch p's interior first uses; its slots of shared points into `shared`.
    void patch_first_uses(int p, FirstMet<std::uint64_t, MixHash>& seen, std::vector<int>& first_of,
                          std::vector<int>& shared);

    const std::vector<Subpatch>& subpatches_;
    const std::vector<int>& leaf_start_;
    const EdgeGraph& graph_;
    int threads_;
    VertexRegistry& vr_;
    SubpatchRings& rings_;
    const PreviousRings& previous_;
    int count_, np_;
    std::vector<int> first_; // the slot of the key's first use
};

void ParallelNumbering::keys() {
    const std::vector<int>& ring_start = rings_.start;
    const std::vector<RingVertex>& ring = rings_.vertices;
    std::vector<VertexKey>& key = rings_.keys;
    reserve_touched(key, ring.size(), threads_);
    key.resize(ring.size());
    reserve_touched(first_, ring.size(), threads_);
    first_.resize(ring.size());
    // A ring copied from the previous pass has its keys (the same slots and,
    // without seam vertices or aliases, the same keys): copied too (most
    // patches in a later pass).
    const PreviousRings& previous = previous_;
    const bool old_keys =
        previous.positions && previous.rings->keys.size() == previous.rings->vertices.size();
    pull_blocks(count_, kSubpatchBlock, threads_, nullptr, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) {
            const int p = subpatches_[i].patch;
            if (old_keys && (*previous.same)[p]) {
                const SubpatchRings& old = *previous.rings;
                const int o = (*previous.previous_start)[p] + i - leaf_start_[p];
                std::copy(old.keys.begin() + old.start[o], old.keys.begin() + old.start[o + 1],
                          key.begin() + ring_start[i]);
                continue;
            }
            for (int j = ring_start[i]; j < ring_start[i + 1]; ++j) {
                const RingVertex& v = ring[j];
                key[j] = canonical_key(
                    vr_, v.foreign >= 0 ? graph_.points[v.foreign].key
                                        : vertex_key(*vr_.match, subpatches_[i].patch, v.s, v.t));
            }
        }
    });
}

void ParallelNumbering::patch_first_uses(int p, FirstMet<std::uint64_t, MixHash>& seen,
                                         std::vector<int>& first_of,
                                         std::vector<int>& shared_slots) {
    const std::vector<int>& ring_start = rings_.start;
    const std::vector<VertexKey>& key = rings_.keys;
    const PreviousRings& previous = previous_;
    const int j0 = ring_start[leaf_start_[p]], j1 = ring_start[leaf_start_[p + 1]];
    const int o = previous.positions ? (*previous.previous_start)[p] : 0;
    const int n = leaf_start_[p + 1] - leaf_start_[p];
    if (previous.positions && (*previous.same)[p] && n > 0) {
        // The previous pass numbered the same rings: one number per key, and
        // the patch's interior points were numbered in its own subpatches,
        // after the centre of the subpatch before.
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
            first_[j] = f;
        }
        return;
    }
    seen.reset(j1 - j0);
    for (int j = j0; j < j1; ++j) {
        if (!interior(j, p)) {
            shared_slots.push_back(j);
            continue;
        }
        const std::uint64_t st =
            (static_cast<std::uint64_t>(key[j].a) << 32) | static_cast<std::uint32_t>(key[j].b);
        first_[j] = seen.emplace(st, j);
    }
}

void ParallelNumbering::first_uses() {
    const std::vector<int>& ring_start = rings_.start;
    const std::vector<int>& leaf_start = leaf_start_;
    // Patches differ in slots by ten times and more (teapot): largest first.
    std::vector<int> order(np_);
    std::iota(order.begin(), order.end(), 0);
    const auto slots = [&](int p) {
        return ring_start[leaf_start[p + 1]] - ring_start[leaf_start[p]];
    };
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return slots(a) > slots(b); });
    // Each patch's slots of shared points (keys not interior to it), in slot
    // order: found here rather than by a scan of every slot on the calling
    // thread.
    std::vector<OwnLine<std::vector<int>>> shared_of(np_); // cache_line.h
    pull_blocks(np_, 1, threads_, &order, [&](int begin, int end) {
        FirstMet<std::uint64_t, MixHash> seen; // (s, t) -> first slot
        std::vector<int> first_of;             // previous vertex number -> first slot
        for (int p = begin; p < end; ++p) patch_first_uses(p, seen, first_of, shared_of[p].value);
    });
    size_t shared_count = 0;
    for (const auto& slots_of_p : shared_of) shared_count += slots_of_p.value.size();
    FirstMet<VertexKey, VertexKeyHash> shared;
    shared.reset(shared_count);
    for (const auto& slots_of_p : shared_of)
        for (int j : slots_of_p.value) first_[j] = shared.emplace(rings_.keys[j], j);
}

void ParallelNumbering::number() {
    const std::vector<int>& ring_start = rings_.start;
    std::vector<RingVertex>& ring = rings_.vertices;
    const std::vector<VertexKey>& key = rings_.keys;
    const std::vector<int>& first = first_;
    const PreviousRings& previous = previous_;
    VertexRegistry& vr = vr_;
    const int count = count_;
    std::vector<int> base(count + 1, 0);
    pull_blocks(count, kSubpatchBlock, threads_, nullptr, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) {
            int fresh = 1; // the centre
            for (int j = ring_start[i]; j < ring_start[i + 1]; ++j) fresh += first[j] == j;
            base[i + 1] = fresh;
        }
    });
    for (int i = 0; i < count; ++i) base[i + 1] += base[i];
    reserve_touched(vr.positions, base[count], threads_);
    vr.positions.resize(base[count]);
    vr.placed.assign(base[count], 1);
    pull_blocks(count, kSubpatchBlock, threads_, nullptr, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) {
            int id = base[i];
            const int p = subpatches_[i].patch;
            if (previous.positions && (*previous.same)[p]) {
                // The same ring, slot by slot, and the same keys.
                const SubpatchRings& old = *previous.rings;
                const int o = (*previous.previous_start)[p] + i - leaf_start_[p];
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
            rings_.centre[i] = id;
            vr.positions[id] = rings_.centre_point[i];
        }
    });
    pull_blocks(count, kSubpatchBlock, threads_, nullptr, [&](int begin, int end) {
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
    else {
        ParallelNumbering numbering(subpatches, leaf_start, graph, threads, vr, rings, previous);
        numbering.keys();
        numbering.first_uses();
        numbering.number();
    }
}

} // namespace seamless
