// SPDX-License-Identifier: MIT
#include <seamless/render/tray/light_planes.h>

#include <stdexcept>
#include <type_traits>

namespace seamless {

LightPlanes& LightPlanes::operator=(const LightPlanes& o) {
    if (this == &o) return *this;
    reset(o.count_ ? o.count_ / o.triangles_ : 0, o.triangles_);
    for (std::size_t i = 0; i < count_; ++i) {
        const std::uint32_t k = o.slot_[i].load(std::memory_order_acquire);
        if (k == 0 || k == kStoring) continue;
        const std::uint32_t mine = stored_->fetch_add(1, std::memory_order_relaxed);
        new (&planes_[mine]) ApexTriangle(o.planes_[k - 1]);
        slot_[i].store(mine + 1, std::memory_order_relaxed);
    }
    return *this;
}

void LightPlanes::reset(std::size_t lights, std::size_t triangles) {
    triangles_ = triangles;
    count_ = lights * triangles;
    // Uninitialised planes (each is written before its slot says formed);
    // value-initialised slots: nothing formed.
    static_assert(std::is_trivially_copyable_v<ApexTriangle> &&
                  std::is_trivially_destructible_v<ApexTriangle>);
    if (count_ >= kStoring) throw std::length_error("LightPlanes: too many planes");
    planes_ = huge_array<ApexTriangle>(count_);
    slot_.reset(count_ ? new std::atomic<std::uint32_t>[count_]() : nullptr);
    stored_ = std::make_unique<std::atomic<std::uint32_t>>(0);
}

std::size_t LightPlanes::formed() const {
    std::size_t n = 0;
    for (std::size_t i = 0; i < count_; ++i) {
        const std::uint32_t k = slot_[i].load(std::memory_order_relaxed);
        n += k != 0 && k != kStoring;
    }
    return n;
}

const ApexTriangle& LightPlanes::get(std::size_t l, std::size_t f, Vec3 apex, Vec3 T1, Vec3 T2,
                                     Vec3 T3, ApexTriangle& scratch) const {
    std::atomic<std::uint32_t>& s = slot_[l * triangles_ + f];
    const std::uint32_t k = s.load(std::memory_order_acquire);
    if (k != 0 && k != kStoring) return planes_[k - 1];
    scratch = apex_triangle(apex, T1, T2, T3);
    std::uint32_t expected = 0;
    if (s.compare_exchange_strong(expected, kStoring, std::memory_order_acq_rel)) {
        const std::uint32_t mine = stored_->fetch_add(1, std::memory_order_relaxed);
        new (&planes_[mine]) ApexTriangle(scratch);
        s.store(mine + 1, std::memory_order_release);
    }
    return scratch;
}

} // namespace seamless
