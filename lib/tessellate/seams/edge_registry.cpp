// SPDX-License-Identifier: MIT
// The edge registry (shared_edges.h): every subpatch side on its line, the
// lines' segments sorted, built per patch in parallel.
#include <seamless/base/check.h>
#include <seamless/base/first_met.h>
#include <seamless/base/parallel/block_schedule.h>
#include <seamless/base/parallel/cache_line.h>
#include <seamless/base/parallel/huge_pages.h>
#include <seamless/base/parallel/parallel.h>
#include <seamless/base/parallel/touched_storage.h>
#include <seamless/tessellate/seams/edge_lines.h>

#include <algorithm>
#include <array>
#include <numeric>
#include <vector>

namespace seamless {

// Side k of rect on its line. A side inside the patch gets its line's key in
// `key` (its line is left to the caller); a side on a patch edge, kNoKey.
SideOnLine locate_side(const BoundaryMatch& m, int patch, const ParamRect& r, int k,
                       std::uint64_t& key) {
    SideOnLine out;
    int edge = -1, dir = 0, c = 0, tag = 0;
    switch (k) {
    case 0:
        out.a = r.s0, out.b = r.s1, dir = 0, c = r.t0, tag = 1, edge = r.t0 == 0 ? 0 : -1;
        break;
    case 1:
        out.a = r.t0, out.b = r.t1, dir = 1, c = r.s1, tag = 0, edge = r.s1 == kParamOne ? 1 : -1;
        break;
    case 2:
        out.a = r.s0, out.b = r.s1, dir = 0, c = r.t1, tag = 0, edge = r.t1 == kParamOne ? 2 : -1;
        break;
    default:
        out.a = r.t0, out.b = r.t1, dir = 1, c = r.s0, tag = 1, edge = r.s0 == 0 ? 3 : -1;
        break;
    }
    key = kNoKey;
    if (edge >= 0) {
        const int pe = 4 * patch + edge;
        if (m.collapsed[pe]) {
            out.line = -1;
            return out;
        }
        out.line = m.edge_group[pe];
        out.side = pe;
        out.reversed = m.edge_reversed[pe] != 0;
        if (out.reversed) {
            const int a = kParamOne - out.b, b = kParamOne - out.a;
            out.a = a, out.b = b;
        }
        return out;
    }
    key = line_key(patch, dir, c);
    out.side = tag;
    return out;
}

// Side k of r lies on a patch edge (its line is a global edge, or none).
bool on_patch_edge(const ParamRect& r, int k) {
    return k == 0 ? r.t0 == 0 : k == 1 ? r.s1 == kParamOne : k == 2 ? r.t1 == kParamOne : r.s0 == 0;
}

// The segment of `line` holding x strictly inside, or nullptr. Sides of one
// tag are disjoint, so each tag's run is searched by bisection.
const LineSegment* containing(const EdgeRegistry& reg, int line, int x) {
    const LineSegment* begin = reg.segments.data() + reg.offsets[line];
    const LineSegment* end = reg.segments.data() + reg.offsets[line + 1];
    while (begin != end) {
        const int tag = begin->side;
        const LineSegment* run_end =
            std::partition_point(begin, end, [tag](const LineSegment& s) { return s.side == tag; });
        const LineSegment* it =
            std::partition_point(begin, run_end, [x](const LineSegment& s) { return s.b <= x; });
        if (it != run_end && it->a < x) return it;
        begin = run_end;
    }
    return nullptr;
}

// Interior line with this key, -1 when no subpatch side lies on it.
int find_interior_line(const EdgeRegistry& reg, std::uint64_t key) {
    auto it = std::lower_bound(reg.interior_keys.begin(), reg.interior_keys.end(), key);
    if (it == reg.interior_keys.end() || *it != key) return -1;
    return reg.interior_lines[it - reg.interior_keys.begin()];
}

SideOnLine side_on_line(const EdgeRegistry& reg, const BoundaryMatch& m, int patch,
                        const ParamRect& r, int k) {
    std::uint64_t key = kNoKey;
    SideOnLine side = locate_side(m, patch, r, k, key);
    if (key != kNoKey) side.line = find_interior_line(reg, key);
    SEAMLESS_CHECK(key == kNoKey || side.line >= 0, "an interior line missing from the registry");
    return side;
}

namespace {

// Patch p's part of build_edge_registry's step (1), on a cache line of its
// own (the workers fill the patches' side by side, cache_line.h).
struct PatchLines {
    std::vector<std::uint64_t> keys; // its interior lines' keys, as first met
    std::vector<int> count;          // sides per interior line
    std::array<int, 4> edge_count{}; // sides per patch edge
};

// A line's segments: by side, then by start.
constexpr auto by_side_then_a = [](const LineSegment& x, const LineSegment& y) {
    return x.side != y.side ? x.side < y.side : x.a < y.a;
};

// build_edge_registry's steps, each patch's part on its own: the subpatches
// by patch (in patch order already when they come from a tessellation): a
// patch's interior lines are its own, so each patch's sides are put on lines
// on its own, in parallel, without shared tables.
class RegistryBuilder {
  public:
    RegistryBuilder(const BoundaryMatch& m, const std::vector<Subpatch>& subpatches, int threads,
                    const PreviousRegistry& previous);
    // (1) Per patch: its sides, its interior lines' keys (sorted: the lines'
    // order), the sides on each of them and on each of its patch edges.
    void collect_lines();
    // (2) The lines' numbers and offsets: the boundary lines first (each
    // patch edge's sides a run of its line), then each patch's interior lines.
    void number_lines();
    // (3) Per patch: its lines' offsets, its sides into their runs, its
    // interior lines sorted; then the boundary lines sorted.
    EdgeRegistry place_sides();

  private:
    void collect_patch(int p, FirstMet<std::uint64_t, MixHash>& met);
    int reuse_patch(int p);
    void place_patch(int p, std::vector<int>& fill, std::vector<int>& by_key);
    int edge_count(int pe) const { return of_patch_[pe / 4].value.edge_count[pe % 4]; }

    const BoundaryMatch& m_;
    const std::vector<Subpatch>& subpatches_;
    int threads_;
    const PreviousRegistry& previous_;
    EdgeRegistry reg_;
    int B_, n_, np_;
    // Patch p's subpatches: by_patch_[first_[p]] to by_patch_[first_[p + 1] - 1].
    std::vector<int> first_, by_patch_;
    std::vector<int> order_; // largest patches first (pull_blocks)
    std::vector<OwnLine<PatchLines>> of_patch_;
    // Per patch taken from the previous registry: its first line there, else -1.
    std::vector<int> old_l0_;
    // Per patch: its first line and segment; per patch edge: its first segment.
    std::vector<int> line_base_, seg_base_, edge_start_;
};

RegistryBuilder::RegistryBuilder(const BoundaryMatch& m, const std::vector<Subpatch>& subpatches,
                                 int threads, const PreviousRegistry& previous)
    : m_(m), subpatches_(subpatches), threads_(threads), previous_(previous) {
    B_ = static_cast<int>(m.group_ref.size());
    reg_.boundary_lines = B_;
    n_ = static_cast<int>(subpatches.size());
    np_ = static_cast<int>(m.collapsed.size()) / 4;
    const int n = n_, np = np_;
    first_.assign(np + 1, 0);
    by_patch_.resize(n);
    for (const Subpatch& sp : subpatches) ++first_[sp.patch + 1];
    for (int p = 0; p < np; ++p) first_[p + 1] += first_[p];
    {
        std::vector<int> fill(first_.begin(), first_.end() - 1);
        for (int i = 0; i < n; ++i) by_patch_[fill[subpatches[i].patch]++] = i;
    }
    order_.resize(np);
    std::iota(order_.begin(), order_.end(), 0);
    std::stable_sort(order_.begin(), order_.end(), [&](int a, int b) {
        return first_[a + 1] - first_[a] > first_[b + 1] - first_[b];
    });
    reserve_huge(reg_.sides, 4 * static_cast<size_t>(n), threads);
    reg_.sides.resize(4 * static_cast<size_t>(n));
}

void RegistryBuilder::collect_lines() {
    of_patch_ = std::vector<OwnLine<PatchLines>>(np_);
    old_l0_.assign(np_, -1);
    pull_blocks(np_, 1, threads_, &order_, [&](int begin, int end) {
        FirstMet<std::uint64_t, MixHash> met;
        for (int p = begin; p < end; ++p) {
            if (previous_.registry && (*previous_.same)[p]) {
                old_l0_[p] = reuse_patch(p);
                continue;
            }
            collect_patch(p, met);
        }
    });
}

void RegistryBuilder::collect_patch(int p, FirstMet<std::uint64_t, MixHash>& met) {
    met.reset(4 * static_cast<size_t>(first_[p + 1] - first_[p]));
    std::vector<std::uint64_t>& k_p = of_patch_[p].value.keys;
    std::vector<int>& c_p = of_patch_[p].value.count;
    for (int j = first_[p]; j < first_[p + 1]; ++j) {
        const int i = by_patch_[j];
        for (int k = 0; k < 4; ++k) {
            std::uint64_t key = kNoKey;
            SideOnLine& side = reg_.sides[4 * i + k];
            side = locate_side(m_, p, subpatches_[i].rect, k, key);
            if (key == kNoKey) {
                if (side.line >= 0) ++of_patch_[p].value.edge_count[side.side % 4];
                continue;
            }
            side.line = met.emplace(key, static_cast<int>(k_p.size())); // local for now
            if (side.line == static_cast<int>(k_p.size())) {
                k_p.push_back(key);
                c_p.push_back(0);
            }
            ++c_p[side.line];
        }
    }
}

// Patch p's part of step (1) from the previous registry (its subpatches from
// previous_start[p] on there): its interior lines' keys in their order there,
// the sides on each, its sides (interior lines local) and the sides on its
// patch edges. Returns its first interior line there.
int RegistryBuilder::reuse_patch(int p) {
    const EdgeRegistry& old = *previous_.registry;
    const int o = (*previous_.previous_start)[p];
    PatchLines& lines = of_patch_[p].value;
    std::vector<std::uint64_t>& keys = lines.keys;
    std::vector<int>& count = lines.count;
    // Its lines: the keys with patch p, numbered l0, l0 + 1, ... there.
    const auto r0 =
        std::lower_bound(old.interior_keys.begin(), old.interior_keys.end(), line_key(p, 0, 0)) -
        old.interior_keys.begin();
    const auto r1 = std::lower_bound(old.interior_keys.begin(), old.interior_keys.end(),
                                     line_key(p + 1, 0, 0)) -
                    old.interior_keys.begin();
    const int nl = static_cast<int>(r1 - r0);
    int l0 = 0;
    if (nl > 0)
        l0 = *std::min_element(old.interior_lines.begin() + r0, old.interior_lines.begin() + r1);
    keys.resize(nl);
    count.resize(nl);
    for (auto r = r0; r < r1; ++r) keys[old.interior_lines[r] - l0] = old.interior_keys[r];
    for (int l = 0; l < nl; ++l) count[l] = old.offsets[l0 + l + 1] - old.offsets[l0 + l];
    for (int j = first_[p]; j < first_[p + 1]; ++j) {
        const int i = by_patch_[j], io = o + j - first_[p];
        for (int k = 0; k < 4; ++k) {
            SideOnLine side = old.sides[4 * static_cast<size_t>(io) + k];
            if (on_patch_edge(subpatches_[i].rect, k)) {
                if (side.line >= 0) ++lines.edge_count[side.side % 4];
            } else {
                side.line -= l0;
            }
            reg_.sides[4 * static_cast<size_t>(i) + k] = side;
        }
    }
    return l0;
}

void RegistryBuilder::number_lines() {
    const int B = B_, np = np_;
    line_base_.assign(np + 1, B);
    for (int p = 0; p < np; ++p)
        line_base_[p + 1] = line_base_[p] + static_cast<int>(of_patch_[p].value.keys.size());
    const int lines = line_base_[np];
    reg_.offsets.assign(lines + 1, 0);
    for (int pe = 0; pe < 4 * np; ++pe)
        if (m_.edge_group[pe] >= 0) reg_.offsets[m_.edge_group[pe] + 1] += edge_count(pe);
    for (int l = 0; l < B; ++l) reg_.offsets[l + 1] += reg_.offsets[l];
    edge_start_.assign(4 * static_cast<size_t>(np), 0);
    {
        std::vector<int> fill(reg_.offsets.begin(), reg_.offsets.begin() + B);
        for (int pe = 0; pe < 4 * np; ++pe)
            if (m_.edge_group[pe] >= 0) {
                edge_start_[pe] = fill[m_.edge_group[pe]];
                fill[m_.edge_group[pe]] += edge_count(pe);
            }
    }
    seg_base_.assign(np + 1, reg_.offsets[B]);
    for (int p = 0; p < np; ++p) {
        int sum = 0;
        for (int c : of_patch_[p].value.count) sum += c;
        seg_base_[p + 1] = seg_base_[p] + sum;
    }
    reg_.offsets[lines] = seg_base_[np];
    reserve_touched(reg_.segments, seg_base_[np], threads_);
    reg_.segments.resize(seg_base_[np]);
    reg_.interior_keys.resize(lines - B);
    reg_.interior_lines.resize(lines - B);
}

void RegistryBuilder::place_patch(int p, std::vector<int>& fill, std::vector<int>& by_key) {
    const int B = B_;
    const std::vector<std::uint64_t>& keys = of_patch_[p].value.keys;
    const std::vector<int>& count = of_patch_[p].value.count;
    const int nl = static_cast<int>(keys.size()), l0 = line_base_[p];
    // Its lines' keys ascending, for look-ups (a patch's keys follow the
    // previous patch's).
    by_key.resize(nl);
    std::iota(by_key.begin(), by_key.end(), 0);
    std::sort(by_key.begin(), by_key.end(), [&](int x, int y) { return keys[x] < keys[y]; });
    for (int r = 0; r < nl; ++r) {
        reg_.interior_keys[l0 - B + r] = keys[by_key[r]];
        reg_.interior_lines[l0 - B + r] = l0 + by_key[r];
    }
    fill.resize(nl);
    for (int l = 0, at = seg_base_[p]; l < nl; ++l) {
        reg_.offsets[l0 + l] = fill[l] = at;
        at += count[l];
    }
    // A patch taken from the previous registry: its interior lines' runs as
    // they were (sorted).
    const bool reused = old_l0_[p] >= 0;
    if (reused) {
        const EdgeRegistry& old = *previous_.registry;
        std::copy(old.segments.begin() + old.offsets[old_l0_[p]],
                  old.segments.begin() + old.offsets[old_l0_[p] + nl],
                  reg_.segments.begin() + seg_base_[p]);
    }
    int edge_fill[4];
    for (int e = 0; e < 4; ++e) edge_fill[e] = edge_start_[4 * p + e];
    for (int j = first_[p]; j < first_[p + 1]; ++j) {
        const int i = by_patch_[j];
        for (int k = 0; k < 4; ++k) {
            SideOnLine& side = reg_.sides[4 * i + k];
            if (side.line < 0) continue;
            const LineSegment seg{side.a, side.b, side.side};
            if (on_patch_edge(subpatches_[i].rect, k)) {
                reg_.segments[edge_fill[side.side % 4]++] = seg;
            } else {
                if (!reused) reg_.segments[fill[side.line]++] = seg;
                side.line += l0;
            }
        }
    }
    // Line l's run ends where its fill stopped (the next line's offset may
    // belong to another patch, not written yet).
    if (!reused)
        for (int l = 0; l < nl; ++l)
            std::sort(reg_.segments.begin() + reg_.offsets[l0 + l], reg_.segments.begin() + fill[l],
                      by_side_then_a);
    std::vector<std::uint64_t>().swap(of_patch_[p].value.keys);
}

EdgeRegistry RegistryBuilder::place_sides() {
    pull_blocks(np_, 1, threads_, &order_, [&](int begin, int end) {
        std::vector<int> fill, key_order;
        for (int p = begin; p < end; ++p) place_patch(p, fill, key_order);
    });
    parallel_chunks(B_, threads_, [&](int begin, int end) {
        for (int l = begin; l < end; ++l)
            std::sort(reg_.segments.begin() + reg_.offsets[l],
                      reg_.segments.begin() + reg_.offsets[l + 1], by_side_then_a);
    });
    return std::move(reg_);
}

} // namespace

EdgeRegistry build_edge_registry(const BoundaryMatch& m, const std::vector<Subpatch>& subpatches,
                                 int threads, const PreviousRegistry& previous) {
    RegistryBuilder builder(m, subpatches, threads, previous);
    builder.collect_lines();
    builder.number_lines();
    return builder.place_sides();
}

void points_inside(const EdgeRegistry& reg, const SideOnLine& side, std::vector<int>& out) {
    if (side.line < 0) return;
    const size_t first = out.size();
    const LineSegment* begin = reg.segments.data() + reg.offsets[side.line];
    const LineSegment* end = reg.segments.data() + reg.offsets[side.line + 1];
    while (begin != end) {
        const int tag = begin->side;
        const LineSegment* run_end =
            std::partition_point(begin, end, [tag](const LineSegment& s) { return s.side == tag; });
        if (tag != side.side) {
            const int a = side.a, b = side.b;
            for (const LineSegment* it = std::partition_point(
                     begin, run_end, [a](const LineSegment& s) { return s.b <= a; });
                 it != run_end && it->a < b; ++it) {
                if (it->a > a) out.push_back(it->a);
                if (it->b < b) out.push_back(it->b);
            }
        }
        begin = run_end;
    }
    std::sort(out.begin() + first, out.end());
    out.erase(std::unique(out.begin() + first, out.end()), out.end());
}

} // namespace seamless
