// SPDX-License-Identifier: MIT
#include <seamless/render/light_planes.h>

#include <type_traits>

namespace seamless {

LightPlanes& LightPlanes::operator=(const LightPlanes& o) {
    if (this == &o) return *this;
    reset(o.count_ ? o.count_ / o.triangles_ : 0, o.triangles_);
    for (std::size_t i = 0; i < count_; ++i)
        if (o.state_[i].load(std::memory_order_acquire) == 2) {
            new (&planes_[i]) ApexTriangle(o.planes_[i]);
            state_[i].store(2, std::memory_order_relaxed);
        }
    return *this;
}

void LightPlanes::reset(std::size_t lights, std::size_t triangles) {
    triangles_ = triangles;
    count_ = lights * triangles;
    // Uninitialised planes (each is written before its state says formed);
    // value-initialised states: nothing formed.
    static_assert(std::is_trivially_copyable_v<ApexTriangle> &&
                  std::is_trivially_destructible_v<ApexTriangle>);
    planes_.reset(count_ ? static_cast<ApexTriangle*>(::operator new(count_ * sizeof(ApexTriangle)))
                         : nullptr);
    state_.reset(count_ ? new std::atomic<unsigned char>[count_]() : nullptr);
}

std::size_t LightPlanes::formed() const {
    std::size_t n = 0;
    for (std::size_t i = 0; i < count_; ++i) n += state_[i].load(std::memory_order_relaxed) == 2;
    return n;
}

const ApexTriangle& LightPlanes::get(std::size_t l, std::size_t f, Vec3 apex, Vec3 T1, Vec3 T2,
                                     Vec3 T3, ApexTriangle& scratch) const {
    const std::size_t i = l * triangles_ + f;
    std::atomic<unsigned char>& s = state_[i];
    if (s.load(std::memory_order_acquire) == 2) return planes_[i];
    scratch = apex_triangle(apex, T1, T2, T3);
    unsigned char expected = 0;
    if (s.compare_exchange_strong(expected, 1, std::memory_order_acq_rel)) {
        new (&planes_[i]) ApexTriangle(scratch);
        s.store(2, std::memory_order_release);
    }
    return scratch;
}

} // namespace seamless
