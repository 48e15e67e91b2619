// SPDX-License-Identifier: MIT
// The lines of shared_edges.h's edge registry (edge_registry.cpp), for the
// vertex registry (vertex_registry.cpp): keys of a patch's interior lines,
// where a subpatch side lies, the segment holding a point. Internal to
// lib/tessellate.
#pragma once

#include <seamless/tessellate/seams/shared_edges.h>

#include <cstdint>

namespace seamless {

// Key of a patch's interior line: direction dir at grid coordinate c.
inline constexpr std::uint64_t line_key(int patch, int dir, int c) {
    return (static_cast<std::uint64_t>(patch) << 32) | (static_cast<std::uint64_t>(dir) << 31) |
           static_cast<std::uint64_t>(c);
}

inline constexpr std::uint64_t kNoKey = ~std::uint64_t{0};

// Side k of rect on its line. A side inside the patch gets its line's key in
// `key` (its line is left to the caller); a side on a patch edge, kNoKey.
SideOnLine locate_side(const BoundaryMatch& m, int patch, const ParamRect& r, int k,
                       std::uint64_t& key);

// Side k of r lies on a patch edge (its line is a global edge, or none).
bool on_patch_edge(const ParamRect& r, int k);

// The segment of `line` holding x strictly inside, or nullptr. Sides of one
// tag are disjoint, so each tag's run is searched by bisection.
const LineSegment* containing(const EdgeRegistry& reg, int line, int x);

// Interior line with this key, -1 when no subpatch side lies on it.
int find_interior_line(const EdgeRegistry& reg, std::uint64_t key);

} // namespace seamless
