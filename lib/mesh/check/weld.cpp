// SPDX-License-Identifier: MIT
#include <seamless/mesh/check/bits_hash.h>
#include <seamless/mesh/check/weld.h>

#include <seamless/base/check.h>

#include <algorithm>
#include <climits>
#include <cstdint>
#include <cstring>
#include <map>
#include <numeric>
#include <unordered_map>

namespace seamless {

namespace {

// Copies of the vertices several bodies use (weld_vertices).
void split_bodies(WeldedMesh& W) {
    const int nv = static_cast<int>(W.positions.size());
    std::vector<int> owner(nv, INT_MIN);     // the body keeping vertex v; INT_MIN: none yet
    std::map<std::pair<int, int>, int> copy; // (vertex, body) -> its copy
    for (size_t t = 0; t < W.triangles.size(); ++t) {
        const int b = W.triangle_body[t];
        for (int& v : W.triangles[t]) {
            if (owner[v] == INT_MIN) owner[v] = b;
            if (owner[v] == b) continue;
            auto [it, added] = copy.try_emplace({v, b}, static_cast<int>(W.positions.size()));
            if (added) W.positions.push_back(W.positions[v]);
            v = it->second;
        }
    }
    W.body_copies = static_cast<int>(W.positions.size()) - nv;
}

} // namespace

WeldedMesh weld_vertices(const TriangleMesh& mesh, bool weld, std::vector<int> triangle_body) {
    WeldedMesh W;
    const int nv_in = mesh.vertex_count(), nf = mesh.triangle_count();
    std::vector<int> remap(nv_in);
    if (weld) {
        std::unordered_map<std::array<uint64_t, 3>, int, BitsHash> first;
        first.reserve(nv_in);
        for (int i = 0; i < nv_in; ++i) {
            std::array<uint64_t, 3> k;
            std::memcpy(k.data(), &mesh.positions[i], sizeof k);
            auto [it, inserted] = first.try_emplace(k, static_cast<int>(W.positions.size()));
            if (inserted) W.positions.push_back(mesh.positions[i]);
            remap[i] = it->second;
        }
    } else {
        std::iota(remap.begin(), remap.end(), 0);
        W.positions = mesh.positions;
    }
    W.welded_vertices = nv_in - static_cast<int>(W.positions.size());
    W.triangles.resize(nf);
    for (int t = 0; t < nf; ++t)
        for (int c = 0; c < 3; ++c) W.triangles[t][c] = remap[mesh.triangles[t][c]];
    if (!triangle_body.empty()) {
        SEAMLESS_CHECK(static_cast<int>(triangle_body.size()) == nf, "one body per triangle");
        W.triangle_body = std::move(triangle_body);
        split_bodies(W);
    }
    W.referenced.assign(W.positions.size(), 0);
    for (const auto& t : W.triangles)
        for (int v : t) W.referenced[v] = 1;
    W.unreferenced_vertices =
        static_cast<int>(std::count(W.referenced.begin(), W.referenced.end(), 0));
    return W;
}

} // namespace seamless
