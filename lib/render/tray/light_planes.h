// SPDX-License-Identifier: MIT
// The planes of the shadow pyramids of SHADE step 2 (paper section 7; the
// pyramid from a light over a box of points against a triangle, ray_cluster.h's
// ApexTriangle), per light and triangle, formed on first use and kept for the
// rest of the render. A render uses a fraction of them (about a quarter on
// the teapot scene), so forming all up front cost more than it saved.
// Threads may ask for the same plane at once: each forms it (a pure function
// of the light and the triangle's corners, so the same bits either way), the
// first to claim the entry stores it, the others use their own copy. The
// answers of pyramid_may_meet_triangle do not depend on the thread count.
#pragma once

#include <seamless/base/parallel/huge_pages.h>
#include <seamless/base/vec.h>
#include <seamless/render/tray/ray_cluster.h>

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <vector>

namespace seamless {

class LightPlanes {
  public:
    LightPlanes() = default;
    LightPlanes(const LightPlanes& o) { *this = o; }
    LightPlanes& operator=(const LightPlanes& o);
    LightPlanes(LightPlanes&&) = default;
    LightPlanes& operator=(LightPlanes&&) = default;

    // Room for `lights` x `triangles` planes, none formed yet.
    void reset(std::size_t lights, std::size_t triangles);
    bool empty() const { return count_ == 0; }
    std::size_t size() const { return count_; }
    // Planes formed so far (for tests and --stats).
    std::size_t formed() const;

    // apex_triangle(apex, T1, T2, T3) of light l and triangle f (apex: light
    // l's position, T: triangle f's corners); `scratch` holds it when another
    // thread is storing the entry.
    const ApexTriangle& get(std::size_t l, std::size_t f, Vec3 apex, Vec3 T1, Vec3 T2, Vec3 T3,
                            ApexTriangle& scratch) const;

  private:
    // Raw storage filled in the order planes are formed: planes_[k - 1] for
    // slot_[i] == k, so the planes a render forms lie together (indexed by
    // light and triangle they were spread over many more pages, each a page
    // fault); in huge pages (huge_pages.h) from 512 KB up.
    static constexpr std::uint32_t kStoring = ~std::uint32_t{0};
    std::size_t triangles_ = 0, count_ = 0;
    // slot_[i]: 0 not formed, kStoring being stored, else 1 + its place in planes_.
    mutable HugeArray<ApexTriangle> planes_;
    mutable std::unique_ptr<std::atomic<std::uint32_t>[]> slot_;
    mutable std::unique_ptr<std::atomic<std::uint32_t>> stored_; // planes_ used
};

} // namespace seamless
