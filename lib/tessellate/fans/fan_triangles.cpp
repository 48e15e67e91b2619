// SPDX-License-Identifier: MIT
#include <seamless/base/parallel/block_schedule.h>
#include <seamless/base/parallel/huge_pages.h>
#include <seamless/base/parallel/parallel.h>
#include <seamless/base/parallel/touched_storage.h>
#include <seamless/spline/surface_point.h>
#include <seamless/tessellate/fans/fan_triangles.h>
#include <seamless/tessellate/subdivision/patch_tree.h>

#include <algorithm>
#include <array>
#include <numeric>

namespace seamless {

FanNormals fan_normals(const std::vector<BezierPatch>& patches,
                       const std::vector<Subpatch>& subpatches, const std::vector<int>& leaf_start,
                       const SubpatchRings& rings, int threads) {
    const int count = static_cast<int>(subpatches.size());
    const int np = static_cast<int>(leaf_start.size()) - 1;
    FanNormals normals;
    reserve_huge(normals.ring, rings.vertices.size(), threads);
    normals.ring.resize(rings.vertices.size());
    reserve_touched(normals.centre, count, threads);
    normals.centre.resize(count);
    // A vertex is on the rings of up to four subpatches of a patch: its normal
    // there, where regular (regular_unit_normal), is computed at its first
    // slot in a run of the patch's subpatches and copied to the run's later
    // slots with the same parameters. Runs of at most kRun subpatches of one
    // patch (a model of one patch still takes every worker), largest first.
    constexpr int kRun = 256;
    std::vector<std::array<int, 3>> runs; // patch, first subpatch, end
    for (int p = 0; p < np; ++p)
        for (int i = leaf_start[p]; i < leaf_start[p + 1]; i += kRun)
            runs.push_back({p, i, std::min(i + kRun, leaf_start[p + 1])});
    const int nr = static_cast<int>(runs.size());
    std::vector<int> order(nr);
    std::iota(order.begin(), order.end(), 0);
    const auto slots = [&](int r) { return rings.start[runs[r][2]] - rings.start[runs[r][1]]; };
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return slots(a) > slots(b); });
    pull_blocks(nr, 1, threads, &order, [&](int r, int) {
        const auto [p, i0, i1] = runs[r];
        const BezierPatch& b = patches[p];
        // The vertices first met in the run: numbered after the centre of the
        // subpatch before it, up to its last centre (vertex_numbering.h).
        const int lo = i0 > 0 ? rings.centre[i0 - 1] + 1 : 0, hi = rings.centre[i1 - 1];
        // Per such vertex: the slot whose regular normal it has, or -1.
        std::vector<int> known(hi - lo + 1, -1);
        for (int i = i0; i < i1; ++i) {
            const Subpatch& sp = subpatches[i];
            const double sc = 0.5 * (param_of(sp.rect.s0) + param_of(sp.rect.s1));
            const double tc = 0.5 * (param_of(sp.rect.t0) + param_of(sp.rect.t1));
            normals.centre[i] = unit_normal(b, sc, tc, sc, tc);
            for (int j = rings.start[i]; j < rings.start[i + 1]; ++j) {
                const RingVertex& v = rings.vertices[j];
                // A vertex met before the run is computed at each of its slots.
                int* k = v.vertex >= lo && v.vertex <= hi ? &known[v.vertex - lo] : nullptr;
                if (k && *k >= 0 && rings.vertices[*k].fs == v.fs && rings.vertices[*k].ft == v.ft)
                    normals.ring[j] = normals.ring[*k];
                else if (k && *k < 0 && regular_unit_normal(b, v.fs, v.ft, normals.ring[j]))
                    *k = j;
                else
                    normals.ring[j] = unit_normal(b, v.fs, v.ft, sc, tc);
            }
        }
    });
    return normals;
}

void write_fans(const std::vector<BezierPatch>& patches, const SubpatchRings& rings,
                const FanNormals& normals, const std::vector<int>* node_start,
                std::vector<Vec3>&& positions, double hull_scale, int threads, Tessellation& out) {
    const size_t count = out.subpatches.size();
    const std::vector<int>& ring_start = rings.start;
    const std::vector<RingVertex>& ring = rings.vertices;
    TriangleMesh& mesh = out.mesh;
    TessellationStats& st = out.stats;
    pull_blocks(static_cast<int>(count), kSubpatchBlock, threads, nullptr, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) {
            const int first = ring_start[i], n = ring_start[i + 1] - first;
            int c = 0;
            for (int k = 0; k < n; ++k)
                c += ring[first + k].vertex != ring[first + (k + 1) % n].vertex;
            out.subpatches[i].triangle_count = c;
        }
    });
    std::vector<int> fan_node(count + 1);
    int triangles = 0;
    fan_node[0] = static_cast<int>(out.trees.nodes.size());
    for (size_t i = 0; i < count; ++i) {
        Subpatch& sp = out.subpatches[i];
        sp.first_triangle = triangles;
        triangles += sp.triangle_count;
        fan_node[i + 1] = fan_node[i] + attached_nodes(sp.triangle_count);
        st.max_depth = std::max(st.max_depth, sp.depth);
        if (!sp.planar) ++st.nonplanar_subpatches;
    }
    // The five arrays grow side by side: each resize writes its new elements
    // on one thread. The tree nodes (with the subdivision's copied over) are
    // the largest: second, so that another worker takes them at once; the
    // mesh arrays in their former order (the triangles first: with the nodes
    // first the orientation's reads of them were about 1 ms slower).
    const auto grow = [threads](auto& v, size_t n) {
        reserve_huge(v, n, threads);
        v.resize(n);
    };
    pull_blocks(5, 1, threads, nullptr, [&](int k, int) {
        switch (k) {
        case 0:
            grow(mesh.triangles, triangles);
            break;
        case 1:
            if (node_start) grow(out.trees.nodes, fan_node[count]);
            break;
        case 2:
            grow(mesh.triangle_surface, triangles);
            break;
        case 3:
            grow(mesh.corner_normals, triangles);
            break;
        default:
            grow(mesh.corner_uvs, triangles);
            break;
        }
    });
    // Hulls bottom-up: each fan's subtree as it is written, then each patch's
    // nodes above them.
    const auto scaled = [hull_scale](Box3& b) {
        if (hull_scale != 1 && !b.empty()) b = {hull_scale * b.lo, hull_scale * b.hi};
    };
    const auto triangle_box = [&mesh, &positions, &scaled](int f) {
        Box3 bb;
        for (int v : mesh.triangles[f]) bb.extend(positions[v]);
        scaled(bb);
        return bb;
    };
    std::vector<int> added(count);
    pull_blocks(static_cast<int>(count), kSubpatchBlock, threads, nullptr, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) {
            const Subpatch& sp = out.subpatches[i];
            const BezierPatch& b = patches[sp.patch];
            const ParamRect& r = sp.rect;
            const double sc = 0.5 * (param_of(r.s0) + param_of(r.s1));
            const double tc = 0.5 * (param_of(r.t0) + param_of(r.t1));
            const int first = ring_start[i], n = ring_start[i + 1] - first;
            int f = sp.first_triangle;
            for (int k = 0; k < n; ++k) {
                const RingVertex &a = ring[first + k], &c = ring[first + (k + 1) % n];
                if (a.vertex == c.vertex) continue;
                mesh.triangles[f] = {rings.centre[i], a.vertex, c.vertex};
                mesh.triangle_surface[f] = b.surface;
                mesh.corner_normals[f] = {normals.centre[i], normals.ring[first + k],
                                          normals.ring[first + (k + 1) % n]};
                mesh.corner_uvs[f] = {std::array<double, 2>{b.u_at(sc), b.v_at(tc)},
                                      std::array<double, 2>{b.u_at(a.fs), b.v_at(a.ft)},
                                      std::array<double, 2>{b.u_at(c.fs), b.v_at(c.ft)}};
                ++f;
            }
            // Proposition 11, remark 2: the triangles become the leaves below the subpatch.
            if (!node_start) continue;
            added[i] = attach_triangles_at(out.trees, sp.node, sp.first_triangle, sp.triangle_count,
                                           fan_node[i]);
            update_triangle_hulls(out.trees, fan_node[i], fan_node[i + 1], triangle_box);
        }
    });
    if (node_start) {
        for (size_t i = 0; i < count; ++i)
            out.trees.depth = std::max(out.trees.depth, out.subpatches[i].depth + added[i]);
        const std::vector<int>& at = *node_start;
        const int np = static_cast<int>(at.size()) - 1;
        parallel_chunks(np, threads, [&](int begin, int end) {
            for (int p = begin; p < end; ++p) {
                for (int i = at[p]; i < at[p + 1]; ++i) scaled(out.trees.nodes[i].control_hull);
                update_triangle_hulls(out.trees, at[p], at[p + 1], triangle_box);
            }
        });
    }
    mesh.positions = std::move(positions);
}

} // namespace seamless
