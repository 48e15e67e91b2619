// SPDX-License-Identifier: MIT
// Storage for large arrays written once per render (the image's pixels, the
// light planes, the PNG's bytes): from 512 KB up in 2 MB-aligned pages advised for transparent
// huge pages (madvise; /sys/kernel/mm/transparent_hugepage/enabled is
// "madvise" here), else operator new. A 4 KB page's first touch costs ~12 us
// on this VM (an image's 2,250 pages at 1280x1024: ~26 ms of the render's
// CPU); a test program writing 8 MB took 25-31 ms of CPU in 4 KB pages and
// 0.7-2.4 ms advised (2026-12-02; bench/render/render_assessment.md, i10o).
// Where the kernel has no huge page free it falls back to 4 KB pages.
#pragma once

#include <cstddef>
#include <memory>
#include <type_traits>

namespace seamless {

void* allocate_huge(std::size_t bytes);
// p from allocate_huge(bytes), the same bytes.
void release_huge(void* p, std::size_t bytes);

struct ReleaseHuge {
    std::size_t bytes = 0;
    void operator()(void* p) const { release_huge(p, bytes); }
};
// Storage for n objects of T, none constructed (as raw_array.h's RawArray).
template <class T> using HugeArray = std::unique_ptr<T[], ReleaseHuge>;

template <class T> HugeArray<T> huge_array(std::size_t n) {
    static_assert(std::is_trivially_destructible_v<T>);
    const std::size_t bytes = n * sizeof(T);
    return HugeArray<T>(n ? static_cast<T*>(allocate_huge(bytes)) : nullptr, ReleaseHuge{bytes});
}

} // namespace seamless
