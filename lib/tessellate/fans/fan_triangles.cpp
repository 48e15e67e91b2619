// SPDX-License-Identifier: MIT
#include <seamless/base/check.h>
#include <seamless/base/parallel/block_schedule.h>
#include <seamless/base/parallel/huge_pages.h>
#include <seamless/base/parallel/parallel.h>
#include <seamless/base/parallel/touched_storage.h>
#include <seamless/spline/surface_point.h>
#include <seamless/tessellate/fans/fan_triangles.h>
#include <seamless/tessellate/subdivision/patch_tree.h>

#include <algorithm>
#include <array>
#include <functional>
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

namespace {

// write_fans' steps over one pass's Tessellation.
class FanWriter {
  public:
    // `remap`: each vertex's index in `positions` (empty: the numbering's).
    FanWriter(const FanSources& in, const std::vector<Vec3>& positions,
              const std::vector<int>& remap, Tessellation& out)
        : in_(in), rings_(*in.rings), positions_(positions), remap_(remap), out_(out),
          mesh_(out.mesh), count_(out.subpatches.size()) {}

    // Each subpatch's triangle count (none where two ring vertices are one)
    // and first triangle; where each fan's nodes start (one more entry: the
    // end); stats max_depth and nonplanar_subpatches.
    std::vector<int> count_triangles();
    // The mesh arrays and tree nodes at their sizes.
    void grow(const std::vector<int>& fan_node);
    // The triangles, in parallel; with trees, each fan's leaves below its
    // subpatch and their hulls. Per subpatch: how many levels its leaves add.
    std::vector<int> write_triangles(const std::vector<int>& fan_node);
    // Each patch's nodes above the fans: control hulls scaled, triangle hulls.
    void patch_hulls(const std::vector<int>& added);

  private:
    void scaled(Box3& b) const {
        if (in_.hull_scale != 1 && !b.empty()) b = {in_.hull_scale * b.lo, in_.hull_scale * b.hi};
    }
    Box3 triangle_box(int f) const {
        Box3 bb;
        for (int v : mesh_.triangles[f]) bb.extend(positions_[v]);
        scaled(bb);
        return bb;
    }

    int vertex(int v) const { return remap_.empty() ? v : remap_[v]; }

    const FanSources& in_;
    const SubpatchRings& rings_;
    const std::vector<Vec3>& positions_;
    const std::vector<int>& remap_;
    Tessellation& out_;
    TriangleMesh& mesh_;
    size_t count_;
    int triangles_ = 0;
};

std::vector<int> FanWriter::count_triangles() {
    const std::vector<int>& ring_start = rings_.start;
    const std::vector<RingVertex>& ring = rings_.vertices;
    pull_blocks(
        static_cast<int>(count_), kSubpatchBlock, in_.threads, nullptr, [&](int begin, int end) {
            for (int i = begin; i < end; ++i) {
                const int first = ring_start[i], n = ring_start[i + 1] - first;
                int c = 0;
                for (int k = 0; k < n; ++k)
                    c += ring[first + k].vertex != ring[first + (k + 1) % n].vertex;
                out_.subpatches[i].triangle_count = out_.subpatches[i].diagonal >= 0 ? 2 : c;
            }
        });
    TessellationStats& st = out_.stats;
    std::vector<int> fan_node(count_ + 1);
    fan_node[0] = static_cast<int>(out_.trees.nodes.size());
    for (size_t i = 0; i < count_; ++i) {
        Subpatch& sp = out_.subpatches[i];
        sp.first_triangle = triangles_;
        triangles_ += sp.triangle_count;
        fan_node[i + 1] = fan_node[i] + attached_nodes(sp.triangle_count);
        st.max_depth = std::max(st.max_depth, sp.depth);
        if (!sp.planar) ++st.nonplanar_subpatches;
        if (sp.diagonal >= 0) ++st.two_triangle_subpatches;
    }
    return fan_node;
}

void FanWriter::grow(const std::vector<int>& fan_node) {
    // The five arrays grow side by side: each resize writes its new elements
    // on one thread. The tree nodes (with the subdivision's copied over) are
    // the largest: second, so that another worker takes them at once; the
    // mesh arrays in their former order (the orientation reads the triangles
    // sooner when they come first).
    const int threads = in_.threads;
    const auto grow = [threads](auto& v, size_t n) {
        reserve_huge(v, n, threads);
        v.resize(n);
    };
    const int triangles = triangles_;
    pull_blocks(5, 1, threads, nullptr, [&](int k, int) {
        switch (k) {
        case 0:
            grow(mesh_.triangles, triangles);
            break;
        case 1:
            if (in_.node_start) grow(out_.trees.nodes, fan_node[count_]);
            break;
        case 2:
            grow(mesh_.triangle_surface, triangles);
            break;
        case 3:
            grow(mesh_.corner_normals, triangles);
            break;
        default:
            grow(mesh_.corner_uvs, triangles);
            break;
        }
    });
}

std::vector<int> FanWriter::write_triangles(const std::vector<int>& fan_node) {
    const std::vector<int>& ring_start = rings_.start;
    const std::vector<RingVertex>& ring = rings_.vertices;
    const FanNormals& normals = *in_.normals;
    const auto triangle_box = [this](int f) { return this->triangle_box(f); };
    std::vector<int> added(count_);
    pull_blocks(
        static_cast<int>(count_), kSubpatchBlock, in_.threads, nullptr, [&](int begin, int end) {
            for (int i = begin; i < end; ++i) {
                const Subpatch& sp = out_.subpatches[i];
                const BezierPatch& b = (*in_.patches)[sp.patch];
                const ParamRect& r = sp.rect;
                const double sc = 0.5 * (param_of(r.s0) + param_of(r.s1));
                const double tc = 0.5 * (param_of(r.t0) + param_of(r.t1));
                const int first = ring_start[i], n = ring_start[i + 1] - first;
                int f = sp.first_triangle;
                const auto uv = [&b](const RingVertex& v) {
                    return std::array<double, 2>{b.u_at(v.fs), b.v_at(v.ft)};
                };
                if (sp.diagonal >= 0) {
                    // Two triangles from corner `diagonal` (Subpatch::diagonal).
                    for (int half = 0; half < 2; ++half) {
                        const int k[3] = {first + sp.diagonal, first + sp.diagonal + 1 + half,
                                          first + (sp.diagonal + 2 + half) % 4};
                        mesh_.triangles[f] = {vertex(ring[k[0]].vertex), vertex(ring[k[1]].vertex),
                                              vertex(ring[k[2]].vertex)};
                        mesh_.triangle_surface[f] = b.surface;
                        mesh_.corner_normals[f] = {normals.ring[k[0]], normals.ring[k[1]],
                                                   normals.ring[k[2]]};
                        mesh_.corner_uvs[f] = {uv(ring[k[0]]), uv(ring[k[1]]), uv(ring[k[2]])};
                        ++f;
                    }
                }
                for (int k = 0; k < n && sp.diagonal < 0; ++k) {
                    const RingVertex &a = ring[first + k], &c = ring[first + (k + 1) % n];
                    if (a.vertex == c.vertex) continue;
                    mesh_.triangles[f] = {vertex(rings_.centre[i]), vertex(a.vertex),
                                          vertex(c.vertex)};
                    mesh_.triangle_surface[f] = b.surface;
                    mesh_.corner_normals[f] = {normals.centre[i], normals.ring[first + k],
                                               normals.ring[first + (k + 1) % n]};
                    mesh_.corner_uvs[f] = {std::array<double, 2>{b.u_at(sc), b.v_at(tc)}, uv(a),
                                           uv(c)};
                    ++f;
                }
                // Proposition 11, remark 2: the triangles become the leaves below the subpatch.
                if (!in_.node_start) continue;
                added[i] = attach_triangles_at(out_.trees, sp.node, sp.first_triangle,
                                               sp.triangle_count, fan_node[i]);
                update_triangle_hulls(out_.trees, fan_node[i], fan_node[i + 1], triangle_box);
            }
        });
    return added;
}

void FanWriter::patch_hulls(const std::vector<int>& added) {
    for (size_t i = 0; i < count_; ++i)
        out_.trees.depth = std::max(out_.trees.depth, out_.subpatches[i].depth + added[i]);
    const std::vector<int>& at = *in_.node_start;
    const int np = static_cast<int>(at.size()) - 1;
    const auto triangle_box = [this](int f) { return this->triangle_box(f); };
    parallel_chunks(np, in_.threads, [&](int begin, int end) {
        for (int p = begin; p < end; ++p) {
            for (int i = at[p]; i < at[p + 1]; ++i) scaled(out_.trees.nodes[i].control_hull);
            update_triangle_hulls(out_.trees, at[p], at[p + 1], triangle_box);
        }
    });
}

// The centres of subpatches written as two triangles are no vertices: the
// others' new indices (empty when there are none) and positions. Centres are
// numbered in subpatch order (vertex_numbering.h), so the dropped ones come
// sorted.
std::vector<int> drop_quad_centres(const std::vector<Subpatch>& subpatches,
                                   const SubpatchRings& rings, std::vector<Vec3>& positions,
                                   int threads) {
    std::vector<int> dropped;
    for (size_t i = 0; i < subpatches.size(); ++i)
        if (subpatches[i].diagonal >= 0) dropped.push_back(rings.centre[i]);
    if (dropped.empty()) return {};
    SEAMLESS_CHECK(std::adjacent_find(dropped.begin(), dropped.end(), std::greater_equal<int>()) ==
                       dropped.end(),
                   "the centres of two-triangle subpatches come in increasing order");
    const int nv = static_cast<int>(positions.size());
    std::vector<int> remap(nv);
    size_t d = 0;
    for (int v = 0; v < nv; ++v) {
        while (d < dropped.size() && dropped[d] < v) ++d;
        remap[v] = d < dropped.size() && dropped[d] == v ? -1 : v - static_cast<int>(d);
    }
    std::vector<Vec3> kept;
    reserve_huge(kept, nv - dropped.size(), threads);
    kept.resize(nv - dropped.size());
    parallel_chunks(nv, threads, [&](int begin, int end) {
        for (int v = begin; v < end; ++v)
            if (remap[v] >= 0) kept[remap[v]] = positions[v];
    });
    positions = std::move(kept);
    return remap;
}

} // namespace

void write_fans(const FanSources& in, std::vector<Vec3>&& positions, Tessellation& out) {
    const std::vector<int> remap =
        drop_quad_centres(out.subpatches, *in.rings, positions, in.threads);
    FanWriter writer(in, positions, remap, out);
    const std::vector<int> fan_node = writer.count_triangles();
    writer.grow(fan_node);
    // Hulls bottom-up: each fan's subtree as it is written, then each patch's
    // nodes above them.
    const std::vector<int> added = writer.write_triangles(fan_node);
    if (in.node_start) writer.patch_hulls(added);
    out.mesh.positions = std::move(positions);
}

} // namespace seamless
