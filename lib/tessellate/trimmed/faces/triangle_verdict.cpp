// SPDX-License-Identifier: MIT
#include <seamless/tessellate/trimmed/faces/triangle_verdict.h>

#include <algorithm>

namespace seamless {

namespace {

// The corner the key starts from: the least (u, then v). Corners of one
// domain are distinct points, so a triangle's rotation is unique.
int first_corner(const std::array<Vec3, 3>& uv) {
    int m = 0;
    for (int i = 1; i < 3; ++i)
        if (uv[i].x < uv[m].x || (uv[i].x == uv[m].x && uv[i].y < uv[m].y)) m = i;
    return m;
}

std::array<double, 6> key_of(const std::array<Vec3, 3>& uv, int m) {
    std::array<double, 6> k;
    for (int i = 0; i < 3; ++i) k[2 * i] = uv[(m + i) % 3].x, k[2 * i + 1] = uv[(m + i) % 3].y;
    return k;
}

} // namespace

void AcceptedTriangles::add(const std::array<Vec3, 3>& uv, const std::array<bool, 3>& boundary,
                            const TriangleVerdict& v) {
    const int m = first_corner(uv);
    Entry e;
    e.key = key_of(uv, m);
    for (int i = 0; i < 3; ++i)
        e.boundary[i] = boundary[(m + i) % 3], e.normals[i] = v.normals[(m + i) % 3];
    e.deviation = v.deviation;
    e.drop = v.drop;
    entries_.push_back(e);
}

void AcceptedTriangles::seal() {
    std::sort(entries_.begin(), entries_.end(),
              [](const Entry& a, const Entry& b) { return a.key < b.key; });
}

bool AcceptedTriangles::find(const std::array<Vec3, 3>& uv, const std::array<bool, 3>& boundary,
                             TriangleVerdict& v) const {
    const int m = first_corner(uv);
    const std::array<double, 6> key = key_of(uv, m);
    const auto it =
        std::lower_bound(entries_.begin(), entries_.end(), key,
                         [](const Entry& e, const std::array<double, 6>& k) { return e.key < k; });
    if (it == entries_.end() || it->key != key) return false;
    for (int i = 0; i < 3; ++i)
        if (it->boundary[i] != boundary[(m + i) % 3]) return false;
    v = TriangleVerdict{};
    v.drop = it->drop;
    v.deviation = it->deviation;
    for (int i = 0; i < 3; ++i) v.normals[(m + i) % 3] = it->normals[i];
    return true;
}

} // namespace seamless
