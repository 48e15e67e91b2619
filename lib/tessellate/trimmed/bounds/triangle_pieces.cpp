// SPDX-License-Identifier: MIT
#include <seamless/tessellate/trimmed/bounds/triangle_pieces.h>

#include <cmath>
#include <limits>

namespace seamless {
namespace {

using Polygon = std::vector<PieceCorner>;

// The part of `in` where uv[axis] >= at (keep_above) or <= at, with the new
// corners on the line itself (Sutherland-Hodgman: a convex polygon stays one).
void clip(const Polygon& in, int axis, double at, bool keep_above, Polygon& out) {
    out.clear();
    auto inside = [&](const PieceCorner& c) {
        return keep_above ? c.uv[axis] >= at : c.uv[axis] <= at;
    };
    const size_t n = in.size();
    for (size_t i = 0; i < n; ++i) {
        const PieceCorner& a = in[i];
        const PieceCorner& b = in[(i + 1) % n];
        if (inside(a)) out.push_back(a);
        if (inside(a) != inside(b)) {
            const double tau = (at - a.uv[axis]) / (b.uv[axis] - a.uv[axis]);
            PieceCorner c;
            for (int k = 0; k < 3; ++k)
                c.lambda[k] = a.lambda[k] + tau * (b.lambda[k] - a.lambda[k]);
            for (int k = 0; k < 2; ++k) c.uv[k] = a.uv[k] + tau * (b.uv[k] - a.uv[k]);
            c.uv[axis] = at;
            out.push_back(c);
        }
    }
}

// The part of `in` between lo and hi along axis (either infinite: no bound).
void band(const Polygon& in, int axis, double lo, double hi, Polygon& tmp, Polygon& out) {
    const Polygon* cur = &in;
    if (std::isfinite(lo)) {
        clip(*cur, axis, lo, true, tmp);
        cur = &tmp;
    }
    if (std::isfinite(hi)) {
        clip(*cur, axis, hi, false, out);
        return;
    }
    out = *cur;
}

} // namespace

void cut_triangle(const std::array<UV, 3>& uv, std::span<const double> cuts_u,
                  std::span<const double> cuts_v, std::vector<TrianglePiece>& out) {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    if (cuts_u.empty() && cuts_v.empty()) {
        out.push_back({{PieceCorner{{1, 0, 0}, uv[0]}, PieceCorner{{0, 1, 0}, uv[1]},
                        PieceCorner{{0, 0, 1}, uv[2]}},
                       0,
                       0});
        return;
    }
    const Polygon whole{{{1, 0, 0}, uv[0]}, {{0, 1, 0}, uv[1]}, {{0, 0, 1}, uv[2]}};
    Polygon strip, cell, tmp;
    const int nu = static_cast<int>(cuts_u.size()), nv = static_cast<int>(cuts_v.size());
    for (int i = 0; i <= nu; ++i) {
        band(whole, 0, i > 0 ? cuts_u[i - 1] : -kInf, i < nu ? cuts_u[i] : kInf, tmp, strip);
        if (strip.size() < 3) continue;
        for (int j = 0; j <= nv; ++j) {
            band(strip, 1, j > 0 ? cuts_v[j - 1] : -kInf, j < nv ? cuts_v[j] : kInf, tmp, cell);
            // A fan over the convex cell.
            for (size_t k = 1; k + 1 < cell.size(); ++k)
                out.push_back({{cell[0], cell[k], cell[k + 1]}, i, j});
        }
    }
}

} // namespace seamless
