// SPDX-License-Identifier: MIT
// phi of a final fan (error_bound.h): the map from the fan to its subpatch
// whose distances certified_fan_bound bounds, at the refined vertices of
// every fan triangle, shared with the neighbouring fans (PhiMemo) so that phi
// is continuous over the patch. Internal to certified_fan_bound.cpp.
#pragma once

#include <seamless/tessellate/bounds/error_bound.h>
#include <seamless/tessellate/bounds/surface_feet.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <span>

namespace seamless::feet {

// Sides shared by two fans are split into kSideRefinement pieces, the same
// for both; phi is linear between those points. Inside, a fan triangle is
// refined m = kSideRefinement * 2^k times (k chosen from its derivative bounds).
// Between the shared points phi is linear in the parameters, not a foot, so
// the tangential drift there counts in full: with 2 pieces a fan whose four
// triangles passed at 0.9 of a tolerance could certify at 1.25 of it (teapot,
// lid seams) and the passes never ended; with 4 they agree within a few percent.
constexpr int kSideRefinement = 4;
constexpr int kMaxCertifyRefinement = 16;
// Gauss-Newton steps of phi toward the foot at the refined vertices.
constexpr int kFootSteps = 2;

// phi at a ring vertex and at a shared side's points is a function of the
// patch and those ring points alone (that is what keeps phi continuous), and
// each is met by every fan sharing it (a side by two, a vertex by up to four)
// and by every refinement tried. PhiMemo keeps them per thread for the patch
// asked about last: a hit is a value computed from the bitwise same inputs,
// so the results do not depend on the order of the fans or the thread count.
// Direct-mapped; a hit compares the whole key bit for bit.
struct PhiMemo {
    static constexpr int kSlots = 1024;
    struct Vertex {
        std::uint64_t generation = 0;
        RingPoint p;
        Node phi;
    };
    struct Side {
        std::uint64_t generation = 0;
        RingPoint lo, hi;
        Node canon[kSideRefinement + 1];
    };
    std::uint64_t generation = 0; // 0: nothing kept
    BezierPatch patch;
    // power_basis(patch) when it has one (the bounds run over a patch's
    // subpatches in order, so it is made once per patch and thread).
    bool power = false;
    PowerBasisPatch pb;
    std::array<Vertex, kSlots> vertices;
    std::array<Side, kSlots> sides;

    // Starts a new generation when `b` is not the patch of the last call:
    // its control points compared (only those within its degrees are read).
    void use(const BezierPatch& b);
    static bool same(const RingPoint& a, const RingPoint& b) {
        return std::memcmp(&a, &b, sizeof(RingPoint)) == 0;
    }
    static std::uint64_t hash(const RingPoint& a, std::uint64_t h) {
        std::uint64_t w[sizeof(RingPoint) / 8];
        std::memcpy(w, &a, sizeof w);
        for (std::uint64_t x : w) h = (h ^ x) * 0x9E3779B97F4A7C15ull;
        return h;
    }
    static int slot(std::uint64_t h) { return static_cast<int>((h ^ (h >> 29)) >> 54); }
};
// Keys compared and hashed bit for bit: no padding in a RingPoint.
static_assert(sizeof(RingPoint) == 2 * sizeof(int) + sizeof(Vec3) + 2 * sizeof(double) &&
              sizeof(RingPoint) % 8 == 0);

// A fan as its bound reads it: the subpatch `r` of `patch` (evaluated by
// `S`), its centre vertex and its ring.
struct Fan {
    const BezierPatch& patch;
    const Surface& S;
    const ParamRect& r;
    Vec3 centre;
    std::span<const RingPoint> ring;
};

// The box of a subpatch's parameters and its feet's.
struct ParamBox {
    double s0, s1, t0, t1;
};

// phi at the refined vertices of every fan triangle, refined m times: grid k,
// a, c is centre + a/m (P - centre) + c/m (Q - centre), P Q the ring's k-th
// side. On the radial edges and inside the fan triangles (no other fan's phi
// meets them) phi takes up to `steps` Gauss-Newton steps toward the foot.
class RefinedPhi {
  public:
    static constexpr int K = kMaxCertifyRefinement + 1;

    RefinedPhi(const Fan& fan, int m, int steps, PhiMemo& memo);
    Node& node(size_t k, int a, int c) const { return grids_[(k * K + a) * K + c]; }
    // phi on every radial edge, from the centre to each ring vertex.
    void radial_edges();
    // phi on fan triangle k's edges and inside it.
    void triangle(size_t k);
    // Step (2): the box of all refined vertices' parameters.
    ParamBox box() const;

  private:
    void shared_side(size_t k);
    void inside(size_t k);

    const Fan& fan_;
    int m_, steps_;
    PhiMemo& memo_;
    double sc_, tc_, inner_limit_;
    Node centre_node_;
    // Plain pointers: each thread_local access in a shared library is a call.
    std::array<Node, K>* radial_;
    Node* grids_;
};

} // namespace seamless::feet
