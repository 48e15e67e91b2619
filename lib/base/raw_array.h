// SPDX-License-Identifier: MIT
// An array of n objects' storage with none of them constructed: each is
// constructed (placement new) by whoever fills it, so pages of entries never
// filled are never touched. For trivially destructible types only (nothing is
// destroyed). Used where value-initialising a large array first cost its page
// faults (light planes, projected patches: render/light_planes.h, projection.h).
#pragma once

#include <cstddef>
#include <memory>
#include <new>
#include <type_traits>

namespace seamless {

struct ReleaseRaw {
    void operator()(void* p) const { ::operator delete(p); }
};
template <class T> using RawArray = std::unique_ptr<T[], ReleaseRaw>;

// Storage for n objects of T (empty for n = 0), none constructed.
template <class T> RawArray<T> raw_array(std::size_t n) {
    static_assert(std::is_trivially_destructible_v<T>);
    return RawArray<T>(n ? static_cast<T*>(::operator new(n * sizeof(T))) : nullptr);
}

} // namespace seamless
