// SPDX-License-Identifier: MIT
#include <seamless/base/parallel/huge_pages.h>
#include <seamless/base/parallel/parallel.h>
#include <seamless/base/parallel/touched_storage.h>
#include <seamless/tessellate/seams/surface_orientation.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <mutex>

namespace seamless {
namespace {

// Union-find with parity: flip(x) = parity(x) xor flip(root).
struct ParitySets {
    std::vector<int> parent;
    std::vector<char> parity;
    explicit ParitySets(int n) : parent(n), parity(n, 0) {
        for (int i = 0; i < n; ++i) parent[i] = i;
    }
    std::pair<int, char> find(int x) {
        char p = 0;
        int r = x;
        while (parent[r] != r) {
            p ^= parity[r];
            r = parent[r];
        }
        // Path compression keeping parities relative to the root.
        char q = p;
        while (parent[x] != x) {
            const int next = parent[x];
            const char px = parity[x];
            parent[x] = r;
            parity[x] = q;
            q ^= px;
            x = next;
        }
        return {r, p};
    }
    // Joins a and b with flip(a) xor flip(b) = rel; false when that contradicts.
    bool unite(int a, int b, char rel) {
        auto [ra, pa] = find(a);
        auto [rb, pb] = find(b);
        if (ra == rb) return (pa ^ pb) == rel;
        if (ra > rb) std::swap(ra, rb);
        parent[rb] = ra;
        parity[rb] = static_cast<char>(pa ^ pb ^ rel);
        return true;
    }
};

void flip_triangle(TriangleMesh& m, size_t f) {
    std::swap(m.triangles[f][1], m.triangles[f][2]);
    if (f < m.corner_normals.size()) {
        auto& n = m.corner_normals[f];
        std::swap(n[1], n[2]);
        for (Vec3& v : n) v = -v;
    }
    if (f < m.corner_uvs.size()) std::swap(m.corner_uvs[f][1], m.corner_uvs[f][2]);
}

// The directed uses of every undirected edge, bucketed by the smaller vertex
// (CSR, in triangle order within a bucket): flat arrays, no hashing.
struct EdgeUses {
    std::vector<int> start; // per vertex into `uses`
    struct Use {
        int hi = 0, surface = 0;
        bool forward = false; // runs from the smaller vertex index
    };
    std::vector<Use> uses;
};

// In parallel: the triangles in kUseBlocks blocks; each block counts its uses
// per bucket, then writes them after the earlier blocks' in each bucket: the
// same triangle order in every bucket for any thread count. In the same pass
// over the triangles: each one's dot(p, q x r) (6 times its signed volume
// against the origin) into `volume6`, for the closed components' volumes.
constexpr int kUseBlocks = 8;

EdgeUses edge_uses(const TriangleMesh& mesh, int threads, std::vector<double>& volume6) {
    EdgeUses e;
    const int nv = static_cast<int>(mesh.positions.size());
    const int nt = static_cast<int>(mesh.triangles.size());
    const auto block_begin = [nt](int b) {
        return static_cast<int>(static_cast<long long>(nt) * b / kUseBlocks);
    };
    const auto each_use = [&mesh](int f, auto&& use) {
        for (int k = 0; k < 3; ++k) {
            const int a = mesh.triangles[f][k], b = mesh.triangles[f][(k + 1) % 3];
            if (a != b) use(a, b);
        }
    };
    // at[b][v]: block b's uses in bucket v, then where they start.
    std::vector<std::vector<int>> at(kUseBlocks);
    reserve_touched(volume6, nt, threads);
    volume6.resize(nt);
    parallel_chunks(kUseBlocks, threads, [&](int begin, int end) {
        for (int b = begin; b < end; ++b) {
            std::vector<int>& n = at[b];
            n.assign(nv, 0);
            for (int f = block_begin(b); f < block_begin(b + 1); ++f) {
                each_use(f, [&n](int a, int c) { ++n[std::min(a, c)]; });
                const Vec3 &p = mesh.positions[mesh.triangles[f][0]],
                           &q = mesh.positions[mesh.triangles[f][1]],
                           &r = mesh.positions[mesh.triangles[f][2]];
                volume6[f] = dot(p, cross(q, r));
            }
        }
    });
    assign_touched(e.start, nv + 1, 0, threads);
    parallel_chunks(nv, threads, [&](int begin, int end) {
        for (int v = begin; v < end; ++v)
            for (int b = 0; b < kUseBlocks; ++b) e.start[v + 1] += at[b][v];
    });
    for (int v = 0; v < nv; ++v) e.start[v + 1] += e.start[v];
    parallel_chunks(nv, threads, [&](int begin, int end) {
        for (int v = begin; v < end; ++v)
            for (int b = 0, x = e.start[v]; b < kUseBlocks; ++b) {
                const int n = at[b][v];
                at[b][v] = x;
                x += n;
            }
    });
    reserve_huge(e.uses, e.start.back(), threads);
    e.uses.resize(e.start.back());
    parallel_chunks(kUseBlocks, threads, [&](int begin, int end) {
        for (int b = begin; b < end; ++b) {
            std::vector<int>& fill = at[b];
            for (int f = block_begin(b); f < block_begin(b + 1); ++f) {
                const int surface = mesh.triangle_surface[f];
                each_use(f, [&](int a, int c) {
                    e.uses[fill[std::min(a, c)]++] = {std::max(a, c), surface, a < c};
                });
            }
        }
    });
    return e;
}

// Votes per surface pair (a << 32 | b, a < b): [0] opposite directions
// (keep both), [1] equal directions (flip one); and the open surfaces.
struct SurfaceVotes {
    std::map<std::uint64_t, std::array<int, 2>> votes;
    std::vector<char> open_surface;
};

// An edge used twice, by two surfaces, votes for keeping both (opposite
// directions) or flipping one (equal directions). Surfaces with an edge used
// once or more than twice are open. The buckets are independent: counted in
// parallel, summed (order-free).
SurfaceVotes count_votes(const EdgeUses& e, int ns, int threads) {
    SurfaceVotes out;
    out.open_surface.assign(ns, 0);
    std::mutex merge;
    parallel_chunks(static_cast<int>(e.start.size()) - 1, threads, [&](int begin, int end) {
        std::map<std::uint64_t, std::array<int, 2>> my_votes;
        std::vector<int> my_open;
        for (int v = begin; v < end; ++v) {
            const EdgeUses::Use* first = e.uses.data() + e.start[v];
            const EdgeUses::Use* last = e.uses.data() + e.start[v + 1];
            for (const EdgeUses::Use* u = first; u != last; ++u) {
                // The first use of its edge in this bucket (triangle order).
                bool seen = false;
                for (const EdgeUses::Use* w = first; w != u && !seen; ++w) seen = w->hi == u->hi;
                if (seen) continue;
                int count = 0;
                const EdgeUses::Use* other = nullptr;
                for (const EdgeUses::Use* w = u; w != last; ++w)
                    if (w->hi == u->hi && ++count == 2) other = w;
                if (count != 2) {
                    my_open.push_back(u->surface);
                } else if (other->surface != u->surface) {
                    const int a = std::min(u->surface, other->surface);
                    const int b = std::max(u->surface, other->surface);
                    const auto pair =
                        (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b);
                    ++my_votes[pair][u->forward == other->forward ? 1 : 0];
                }
            }
        }
        const std::lock_guard<std::mutex> lock(merge);
        for (const auto& [pair, v] : my_votes) {
            out.votes[pair][0] += v[0];
            out.votes[pair][1] += v[1];
        }
        for (int s : my_open) out.open_surface[s] = 1;
    });
    return out;
}

// Per surface: whether it is flipped. Per component of `sets`: the
// orientation of most triangles kept; a closed component (every edge used
// twice) then faces outward. `volume6`: each triangle's term of six times the
// signed volume.
std::vector<char> surface_flips(const TriangleMesh& mesh, ParitySets& sets,
                                const std::vector<char>& open_surface,
                                const std::vector<double>& volume6) {
    const int ns = static_cast<int>(mesh.surface_names.size());
    std::vector<int> triangles_of(ns, 0);
    for (int s : mesh.triangle_surface) ++triangles_of[s];
    std::vector<long long> keep(ns, 0); // per root: triangles keeping minus flipping
    std::vector<char> parity(ns);
    std::vector<int> root(ns);
    for (int s = 0; s < ns; ++s) {
        const auto [r, p] = sets.find(s);
        root[s] = r;
        parity[s] = p;
        keep[r] += p ? -triangles_of[s] : triangles_of[s];
    }
    std::vector<char> flip_root(ns, 0);
    for (int s = 0; s < ns; ++s)
        if (root[s] == s) flip_root[s] = keep[s] < 0;
    std::vector<char> open(ns, 0);
    for (int s = 0; s < ns; ++s)
        if (open_surface[s]) open[root[s]] = 1;
    // The terms were computed in parallel with the edge uses; summed here in
    // triangle order, the same sums bit for bit as one loop.
    std::vector<double> volume(ns, 0);
    for (size_t f = 0; f < volume6.size(); ++f) {
        const int s = mesh.triangle_surface[f];
        volume[root[s]] += (parity[s] ^ flip_root[root[s]]) ? -volume6[f] : volume6[f];
    }
    for (int s = 0; s < ns; ++s)
        if (root[s] == s && !open[s] && volume[s] < 0) flip_root[s] ^= 1;
    std::vector<char> flip(ns);
    for (int s = 0; s < ns; ++s) flip[s] = parity[s] ^ flip_root[root[s]];
    return flip;
}

} // namespace

OrientationResult orient_surfaces(TriangleMesh& mesh, int threads) {
    OrientationResult out;
    const int ns = static_cast<int>(mesh.surface_names.size());
    if (ns < 1 || mesh.triangle_surface.size() != mesh.triangles.size()) return out;
    std::vector<double> volume6;
    const EdgeUses e = edge_uses(mesh, threads, volume6);
    const SurfaceVotes votes = count_votes(e, ns, threads);
    // Majority decides, pairs in ascending order; a pair with votes both ways
    // is a conflict.
    ParitySets sets(ns);
    for (const auto& [pair, v] : votes.votes) {
        if (v[0] != 0 && v[1] != 0) ++out.conflicts;
        const char rel = v[1] > v[0] ? 1 : 0;
        if (!sets.unite(static_cast<int>(pair >> 32), static_cast<int>(pair & 0xffffffffu), rel))
            ++out.conflicts;
    }
    const std::vector<char> flip = surface_flips(mesh, sets, votes.open_surface, volume6);
    for (int s = 0; s < ns; ++s) out.flipped_surfaces += flip[s];
    parallel_chunks(mesh.triangle_count(), threads, [&](int begin, int end) {
        for (int f = begin; f < end; ++f)
            if (flip[mesh.triangle_surface[f]]) flip_triangle(mesh, f);
    });
    return out;
}

} // namespace seamless
