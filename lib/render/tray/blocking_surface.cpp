// SPDX-License-Identifier: MIT
// A light blocked by a surface of triangles (blocking_surface.h).
#include <seamless/render/tray/blocking_surface.h>

#include <seamless/render/tray/interval3.h>
#include <seamless/render/tray/ray_cluster.h>

#include <algorithm>

namespace seamless {

using namespace interval3;

std::vector<int> triangle_neighbours(const std::vector<std::array<int, 3>>& triangles) {
    // Directed edges bucketed by their first vertex (counting sort): per
    // bucket entry k the edge's last vertex to[k] and its number 3 t + e (from
    // corner e to corner e + 1 of triangle t), so a vertex's few edges are
    // scanned for the same edge and its reverse in flat arrays (a hash table
    // of every edge touched several times the memory, each fresh page a
    // fault); the last vertices kept in bucket order rather than recomputed
    // from the edge's number.
    const size_t n = triangles.size() * 3;
    int nv = 0;
    for (const auto& t : triangles) nv = std::max({nv, t[0] + 1, t[1] + 1, t[2] + 1});
    std::vector<int> start(static_cast<size_t>(nv) + 1, 0);
    for (const auto& t : triangles)
        for (int e = 0; e < 3; ++e) ++start[t[e] + 1];
    for (int v = 0; v < nv; ++v) start[v + 1] += start[v];
    std::vector<int> edge(n), to(n), cursor(start.begin(), start.end() - 1);
    for (size_t t = 0, h = 0; t < triangles.size(); ++t)
        for (int e = 0; e < 3; ++e, ++h) {
            const int k = cursor[triangles[t][e]]++;
            edge[k] = static_cast<int>(h);
            to[k] = triangles[t][e == 2 ? 0 : e + 1];
        }
    std::vector<int> out(n, -1);
    for (int u = 0; u < nv; ++u)
        for (int k = start[u]; k < start[u + 1]; ++k) {
            // The edge from u to v: traversed by this triangle alone, and the
            // edge from v to u by exactly one triangle.
            const int v = to[k];
            int same = 0;
            for (int j = start[u]; j < start[u + 1]; ++j) same += to[j] == v;
            if (same != 1) continue; // several triangles traverse it: not a manifold edge
            int other = -1, count = 0;
            for (int j = start[v]; j < start[v + 1]; ++j)
                if (to[j] == u) other = edge[j], ++count;
            if (count == 1) out[edge[k]] = other / 3;
        }
    return out;
}

bool pyramid_blocked_by_surface(const LightPyramid& pyramid, int seed, const BlockerMesh& mesh,
                                int skip, int max_size, SurfaceScratch& scratch) {
    const Vec3 apex = pyramid.apex;
    const IVec<3>& ends = pyramid.ends;
    const double q_max = pyramid.q_max;
    const std::vector<Vec3>& positions = mesh.positions;
    const std::vector<std::array<int, 3>>& triangles = mesh.triangles;
    const std::vector<int>& neighbours = mesh.neighbours;
    const std::vector<int>& group = mesh.group;
    if (group[seed] == skip) return false;
    const IV3 L = iv(apex), E{ends[0], ends[1], ends[2]};
    const Vec3 mid{ends[0].mid(), ends[1].mid(), ends[2].mid()};
    // The plane across the pyramid: normal n towards the midpoint; a point X
    // on the ray to P in the box lies at q = n.(X - L) / n.(P - L).
    const IV3 n = isub(iv(mid), L);
    const Interval reach = idot(n, isub(E, L));
    if (!(reach.lo() > 0)) return false;
    const double depth_max = (Interval(q_max) * Interval(reach.lo())).lo();
    auto vertex = [&](int t, int k) { return positions[triangles[t][k]]; };
    // c) first: the ray to the midpoint meets the seed.
    RayCluster ray;
    for (int i = 0; i < 3; ++i) {
        ray.origin[i] = L[i];
        ray.direction[i] = n[i];
    }
    Interval q;
    if (!covers_triangle(ray, vertex(seed, 0), vertex(seed, 1), vertex(seed, 2), q)) return false;
    // The seed's orientation seen from the apex.
    auto facing = [&](int t) {
        const IV3 A = iv(vertex(t, 0)), B = iv(vertex(t, 1)), C = iv(vertex(t, 2));
        const Interval f = idot(icross(isub(B, A), isub(C, A)), isub(A, L));
        return f.lo() > 0 ? 1 : f.hi() < 0 ? -1 : 0;
    };
    // a)'s depth: n.(X - L) over the triangle's bounding box (each coordinate
    // enters once, so the range is exact up to rounding).
    auto between = [&](int t) {
        const Vec3 A = vertex(t, 0), B = vertex(t, 1), C = vertex(t, 2);
        const IV3 X{Interval(std::min({A.x, B.x, C.x}), std::max({A.x, B.x, C.x})),
                    Interval(std::min({A.y, B.y, C.y}), std::max({A.y, B.y, C.y})),
                    Interval(std::min({A.z, B.z, C.z}), std::max({A.z, B.z, C.z}))};
        const Interval d = idot(n, isub(X, L));
        return d.lo() > 0 && d.hi() < depth_max;
    };
    const int sigma = facing(seed);
    if (sigma == 0 || !between(seed)) return false;
    // An edge U V misses the pyramid when the box lies strictly on one side of
    // the plane through the apex, U and V: that plane meets the pyramid only at
    // the apex, which is then not on the line U V.
    auto edge_misses = [&](int t, int e) {
        const IV3 U = iv(vertex(t, e)), V = iv(vertex(t, (e + 1) % 3));
        const IV3 m = icross(isub(U, L), isub(V, L));
        const Interval side = idot(m, isub(E, L));
        return side.lo() > 0 || side.hi() < 0;
    };
    auto& stamp = scratch.stamp;
    if (stamp.size() != triangles.size() || scratch.epoch == ~0u) {
        stamp.assign(triangles.size(), 0);
        scratch.epoch = 0;
    }
    const unsigned in_s = ++scratch.epoch;
    auto& stack = scratch.stack;
    stack.assign(1, seed);
    stamp[seed] = in_s;
    int size = 1;
    while (!stack.empty()) {
        const int t = stack.back();
        stack.pop_back();
        for (int e = 0; e < 3; ++e) {
            if (edge_misses(t, e)) continue; // a border of S that the pyramid misses
            const int nb = neighbours[3 * static_cast<size_t>(t) + e];
            if (nb < 0) return false;
            if (stamp[nb] == in_s) continue;
            if (group[nb] == skip || ++size > max_size || facing(nb) != sigma || !between(nb))
                return false;
            stamp[nb] = in_s;
            stack.push_back(nb);
        }
    }
    return true;
}

} // namespace seamless
