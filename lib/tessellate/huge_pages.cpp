// SPDX-License-Identifier: MIT
#include <seamless/base/parallel.h>
#include <seamless/tessellate/huge_pages.h>

#include <algorithm>
#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#endif
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace seamless {

void advise_huge_pages(void* p, std::size_t bytes) {
#if defined(MADV_HUGEPAGE)
    constexpr std::uintptr_t kHuge = std::uintptr_t{1} << 21;
    const std::uintptr_t begin = (reinterpret_cast<std::uintptr_t>(p) + kHuge - 1) & ~(kHuge - 1);
    const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(p) + bytes) & ~(kHuge - 1);
    // A hint: where it fails (no transparent huge pages) the 4 KB pages stay.
    if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
    (void)p, (void)bytes;
#endif
}

void keep_freed_memory() {
#if defined(__GLIBC__)
    // 32 MB: glibc's largest mmap threshold (HEAP_MAX_SIZE / 2 on 64 bits);
    // setting it also ends its dynamic adjustment.
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
#endif
}

void touch_pages(void* p, std::size_t bytes, int threads) {
    constexpr std::size_t kHuge = std::size_t{1} << 21, kPage = 4096;
    volatile unsigned char* const b = static_cast<unsigned char*>(p);
    const int units = static_cast<int>((bytes + kHuge - 1) / kHuge);
    parallel_chunks(units, threads, [&](int begin, int end) {
        const std::size_t from = begin * kHuge, stop = std::min(bytes, end * kHuge);
#if defined(MADV_POPULATE_WRITE)
        // The pages holding [from, stop) in one call (Linux 5.14): about half
        // the cost of a fault per page here (64 MB: 570 -> 300 ms, i11o).
        // Whole pages of the caller's storage: writable, contents unchanged.
        const std::uintptr_t a = (reinterpret_cast<std::uintptr_t>(p) + from) & ~(kPage - 1);
        const std::uintptr_t z = reinterpret_cast<std::uintptr_t>(p) + stop;
        if (stop > from && madvise(reinterpret_cast<void*>(a), z - a, MADV_POPULATE_WRITE) == 0)
            return;
#endif
        for (std::size_t at = from; at < stop; at += kPage) b[at] = 0;
    });
}

} // namespace seamless
