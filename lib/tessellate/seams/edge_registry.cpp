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

// Patch p's part of build_edge_registry's step (1) from the previous registry
// `old` (its subpatches from o on there): its interior lines' keys in their
// order there, the sides on each, its sides (interior lines local) and the
// sides on its patch edges. Returns its first interior line there.
int reuse_patch(const EdgeRegistry& old, const std::vector<Subpatch>& subpatches,
                const std::vector<int>& by_patch, const std::vector<int>& first, int p, int o,
                PatchLines& lines, std::vector<SideOnLine>& sides) {
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
    for (int j = first[p]; j < first[p + 1]; ++j) {
        const int i = by_patch[j], io = o + j - first[p];
        for (int k = 0; k < 4; ++k) {
            SideOnLine side = old.sides[4 * static_cast<size_t>(io) + k];
            if (on_patch_edge(subpatches[i].rect, k)) {
                if (side.line >= 0) ++lines.edge_count[side.side % 4];
            } else {
                side.line -= l0;
            }
            sides[4 * static_cast<size_t>(i) + k] = side;
        }
    }
    return l0;
}

} // namespace

EdgeRegistry build_edge_registry(const BoundaryMatch& m, const std::vector<Subpatch>& subpatches,
                                 int threads, const PreviousRegistry& previous) {
    EdgeRegistry reg;
    const int B = static_cast<int>(m.group_ref.size());
    reg.boundary_lines = B;
    const int n = static_cast<int>(subpatches.size());
    const int np = static_cast<int>(m.collapsed.size()) / 4;
    // The subpatches by patch (in patch order already when they come from a
    // tessellation): a patch's interior lines are its own, so each patch's
    // sides are put on lines on its own, in parallel, without shared tables.
    std::vector<int> first(np + 1, 0), by_patch(n);
    for (const Subpatch& sp : subpatches) ++first[sp.patch + 1];
    for (int p = 0; p < np; ++p) first[p + 1] += first[p];
    {
        std::vector<int> fill(first.begin(), first.end() - 1);
        for (int i = 0; i < n; ++i) by_patch[fill[subpatches[i].patch]++] = i;
    }
    // Largest patches first (pull_blocks).
    std::vector<int> order(np);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
        return first[a + 1] - first[a] > first[b + 1] - first[b];
    });
    reserve_huge(reg.sides, 4 * static_cast<size_t>(n), threads);
    reg.sides.resize(4 * static_cast<size_t>(n));
    // (1) Per patch: its sides, its interior lines' keys (sorted: the lines'
    // order), the sides on each of them and on each of its patch edges.
    std::vector<OwnLine<PatchLines>> of_patch(np);
    const auto edge_count = [&of_patch](int pe) {
        return of_patch[pe / 4].value.edge_count[pe % 4];
    };
    // Per patch taken from the previous registry: its first line there, else -1.
    std::vector<int> old_l0(np, -1);
    pull_blocks(np, 1, threads, &order, [&](int begin, int end) {
        FirstMet<std::uint64_t, MixHash> met;
        for (int p = begin; p < end; ++p) {
            if (previous.registry && (*previous.same)[p]) {
                old_l0[p] =
                    reuse_patch(*previous.registry, subpatches, by_patch, first, p,
                                (*previous.previous_start)[p], of_patch[p].value, reg.sides);
                continue;
            }
            met.reset(4 * static_cast<size_t>(first[p + 1] - first[p]));
            std::vector<std::uint64_t>& k_p = of_patch[p].value.keys;
            std::vector<int>& c_p = of_patch[p].value.count;
            for (int j = first[p]; j < first[p + 1]; ++j) {
                const int i = by_patch[j];
                for (int k = 0; k < 4; ++k) {
                    std::uint64_t key = kNoKey;
                    SideOnLine& side = reg.sides[4 * i + k];
                    side = locate_side(m, p, subpatches[i].rect, k, key);
                    if (key == kNoKey) {
                        if (side.line >= 0) ++of_patch[p].value.edge_count[side.side % 4];
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
    });
    // (2) The lines' numbers and offsets: the boundary lines first (each
    // patch edge's sides a run of its line), then each patch's interior lines.
    std::vector<int> line_base(np + 1, B);
    for (int p = 0; p < np; ++p)
        line_base[p + 1] = line_base[p] + static_cast<int>(of_patch[p].value.keys.size());
    const int lines = line_base[np];
    reg.offsets.assign(lines + 1, 0);
    for (int pe = 0; pe < 4 * np; ++pe)
        if (m.edge_group[pe] >= 0) reg.offsets[m.edge_group[pe] + 1] += edge_count(pe);
    for (int l = 0; l < B; ++l) reg.offsets[l + 1] += reg.offsets[l];
    std::vector<int> edge_start(4 * static_cast<size_t>(np), 0);
    {
        std::vector<int> fill(reg.offsets.begin(), reg.offsets.begin() + B);
        for (int pe = 0; pe < 4 * np; ++pe)
            if (m.edge_group[pe] >= 0) {
                edge_start[pe] = fill[m.edge_group[pe]];
                fill[m.edge_group[pe]] += edge_count(pe);
            }
    }
    std::vector<int> seg_base(np + 1, reg.offsets[B]);
    for (int p = 0; p < np; ++p) {
        int sum = 0;
        for (int c : of_patch[p].value.count) sum += c;
        seg_base[p + 1] = seg_base[p] + sum;
    }
    reg.offsets[lines] = seg_base[np];
    reserve_touched(reg.segments, seg_base[np], threads);
    reg.segments.resize(seg_base[np]);
    reg.interior_keys.resize(lines - B);
    reg.interior_lines.resize(lines - B);
    // (3) Per patch: its lines' offsets, its sides into their runs, its
    // interior lines sorted; then the boundary lines sorted.
    const auto by_side_then_a = [](const LineSegment& x, const LineSegment& y) {
        return x.side != y.side ? x.side < y.side : x.a < y.a;
    };
    pull_blocks(np, 1, threads, &order, [&](int begin, int end) {
        std::vector<int> fill, key_order;
        for (int p = begin; p < end; ++p) {
            const std::vector<std::uint64_t>& keys = of_patch[p].value.keys;
            const std::vector<int>& count = of_patch[p].value.count;
            const int nl = static_cast<int>(keys.size()), l0 = line_base[p];
            // Its lines' keys ascending, for look-ups (a patch's keys follow
            // the previous patch's).
            std::vector<int>& by_key = key_order;
            by_key.resize(nl);
            std::iota(by_key.begin(), by_key.end(), 0);
            std::sort(by_key.begin(), by_key.end(),
                      [&](int x, int y) { return keys[x] < keys[y]; });
            for (int r = 0; r < nl; ++r) {
                reg.interior_keys[l0 - B + r] = keys[by_key[r]];
                reg.interior_lines[l0 - B + r] = l0 + by_key[r];
            }
            fill.resize(nl);
            for (int l = 0, at = seg_base[p]; l < nl; ++l) {
                reg.offsets[l0 + l] = fill[l] = at;
                at += count[l];
            }
            // A patch taken from the previous registry: its interior lines'
            // runs as they were (sorted).
            const bool reused = old_l0[p] >= 0;
            if (reused) {
                const EdgeRegistry& old = *previous.registry;
                std::copy(old.segments.begin() + old.offsets[old_l0[p]],
                          old.segments.begin() + old.offsets[old_l0[p] + nl],
                          reg.segments.begin() + seg_base[p]);
            }
            int edge_fill[4];
            for (int e = 0; e < 4; ++e) edge_fill[e] = edge_start[4 * p + e];
            for (int j = first[p]; j < first[p + 1]; ++j) {
                const int i = by_patch[j];
                for (int k = 0; k < 4; ++k) {
                    SideOnLine& side = reg.sides[4 * i + k];
                    if (side.line < 0) continue;
                    const LineSegment seg{side.a, side.b, side.side};
                    if (on_patch_edge(subpatches[i].rect, k)) {
                        reg.segments[edge_fill[side.side % 4]++] = seg;
                    } else {
                        if (!reused) reg.segments[fill[side.line]++] = seg;
                        side.line += l0;
                    }
                }
            }
            // Line l's run ends where its fill stopped (the next line's
            // offset may belong to another patch, not written yet).
            if (!reused)
                for (int l = 0; l < nl; ++l)
                    std::sort(reg.segments.begin() + reg.offsets[l0 + l],
                              reg.segments.begin() + fill[l], by_side_then_a);
            std::vector<std::uint64_t>().swap(of_patch[p].value.keys);
        }
    });
    parallel_chunks(B, threads, [&](int begin, int end) {
        for (int l = begin; l < end; ++l)
            std::sort(reg.segments.begin() + reg.offsets[l],
                      reg.segments.begin() + reg.offsets[l + 1], by_side_then_a);
    });
    return reg;
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
