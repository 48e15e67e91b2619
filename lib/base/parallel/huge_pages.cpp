// SPDX-License-Identifier: MIT
#include <seamless/base/parallel/huge_pages.h>
#include <seamless/base/parallel/parallel.h>

#include <algorithm>
#include <cstdint>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace seamless {
namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;
// Below this, operator new: a huge page for less would be mostly unused.
constexpr std::size_t kHugeFrom = kHugePage / 4;

std::size_t huge_bytes(std::size_t bytes) {
    return (bytes + kHugePage - 1) / kHugePage * kHugePage;
}

} // namespace

void* allocate_huge(std::size_t bytes) {
#if defined(__linux__)
    if (bytes < kHugeFrom) return ::operator new(bytes);
    // A mapping one huge page longer, trimmed to the aligned pages inside it.
    const std::size_t size = huge_bytes(bytes);
    void* m =
        mmap(nullptr, size + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (m == MAP_FAILED) throw std::bad_alloc();
    char* const base = static_cast<char*>(m);
    const std::size_t head =
        (kHugePage - reinterpret_cast<std::uintptr_t>(base) % kHugePage) % kHugePage;
    if (head > 0) munmap(base, head);
    munmap(base + head + size, kHugePage - head);
    madvise(base + head, size, MADV_HUGEPAGE); // advice: no huge pages is no error
    return base + head;
#else
    return ::operator new(bytes);
#endif
}

void release_huge(void* p, std::size_t bytes) {
    if (!p) return;
#if defined(__linux__)
    if (bytes >= kHugeFrom) {
        munmap(p, huge_bytes(bytes));
        return;
    }
#else
    (void)bytes;
#endif
    ::operator delete(p);
}

void advise_huge_pages(void* p, std::size_t bytes) {
#if defined(MADV_HUGEPAGE)
    constexpr std::uintptr_t kHuge = kHugePage;
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
    constexpr std::size_t kHuge = kHugePage, kPage = 4096;
    volatile unsigned char* const b = static_cast<unsigned char*>(p);
    const int units = static_cast<int>((bytes + kHuge - 1) / kHuge);
    parallel_chunks(units, threads, [&](int begin, int end) {
        const std::size_t from = begin * kHuge, stop = std::min(bytes, end * kHuge);
#if defined(MADV_POPULATE_WRITE)
        // The pages holding [from, stop) in one call (Linux 5.14), cheaper
        // than a fault per page. Whole pages of the caller's storage:
        // writable, contents unchanged.
        const std::uintptr_t a = (reinterpret_cast<std::uintptr_t>(p) + from) & ~(kPage - 1);
        const std::uintptr_t z = reinterpret_cast<std::uintptr_t>(p) + stop;
        if (stop > from && madvise(reinterpret_cast<void*>(a), z - a, MADV_POPULATE_WRITE) == 0)
            return;
#endif
        for (std::size_t at = from; at < stop; at += kPage) b[at] = 0;
    });
}

} // namespace seamless
