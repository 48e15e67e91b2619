// SPDX-License-Identifier: MIT
#include <seamless/base/parallel.h>
#include <seamless/tessellate/block_schedule.h>
#include <seamless/tessellate/fan_triangles.h>
#include <seamless/tessellate/huge_pages.h>
#include <seamless/tessellate/patch_tree.h>

#include <algorithm>
#include <array>

namespace seamless {

FanNormals fan_normals(const std::vector<BezierPatch>& patches,
                       const std::vector<Subpatch>& subpatches, const SubpatchRings& rings,
                       int threads) {
    const int count = static_cast<int>(subpatches.size());
    FanNormals normals;
    reserve_huge(normals.ring, rings.vertices.size(), threads);
    normals.ring.resize(rings.vertices.size());
    normals.centre.resize(count);
    pull_blocks(count, kSubpatchBlock, threads, nullptr, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) {
            const Subpatch& sp = subpatches[i];
            const BezierPatch& b = patches[sp.patch];
            const double sc = 0.5 * (param_of(sp.rect.s0) + param_of(sp.rect.s1));
            const double tc = 0.5 * (param_of(sp.rect.t0) + param_of(sp.rect.t1));
            normals.centre[i] = unit_normal(b, sc, tc, sc, tc);
            for (int j = rings.start[i]; j < rings.start[i + 1]; ++j)
                normals.ring[j] =
                    unit_normal(b, rings.vertices[j].fs, rings.vertices[j].ft, sc, tc);
        }
    });
    return normals;
}

void write_fans(const std::vector<BezierPatch>& patches, const SubpatchRings& rings,
                const FanNormals& normals, const std::vector<int>& node_start,
                std::vector<Vec3>&& positions, int threads, Tessellation& out) {
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
    const auto grow = [threads](auto& v, size_t n) {
        reserve_huge(v, n, threads);
        v.resize(n);
    };
    grow(mesh.triangles, triangles);
    grow(mesh.triangle_surface, triangles);
    grow(mesh.corner_normals, triangles);
    grow(mesh.corner_uvs, triangles);
    grow(out.trees.nodes, fan_node[count]);
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
            added[i] = attach_triangles_at(out.trees, sp.node, sp.first_triangle, sp.triangle_count,
                                           fan_node[i]);
        }
    });
    for (size_t i = 0; i < count; ++i)
        out.trees.depth = std::max(out.trees.depth, out.subpatches[i].depth + added[i]);
    mesh.positions = std::move(positions);
    // Hulls bottom-up: each fan's subtree, then each patch's nodes above them.
    const auto triangle_box = [&mesh](int f) {
        Box3 bb;
        for (int v : mesh.triangles[f]) bb.extend(mesh.positions[v]);
        return bb;
    };
    pull_blocks(static_cast<int>(count), kSubpatchBlock, threads, nullptr, [&](int begin, int end) {
        for (int i = begin; i < end; ++i)
            update_triangle_hulls(out.trees, fan_node[i], fan_node[i + 1], triangle_box);
    });
    const int np = static_cast<int>(node_start.size()) - 1;
    parallel_chunks(np, threads, [&](int begin, int end) {
        for (int p = begin; p < end; ++p)
            update_triangle_hulls(out.trees, node_start[p], node_start[p + 1], triangle_box);
    });
}

} // namespace seamless
