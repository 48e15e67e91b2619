// SPDX-License-Identifier: MIT
#include <seamless/render/huge_pages.h>

#include <sys/mman.h>

#include <cstdint>
#include <new>

namespace seamless {
namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;
// Below this, operator new: a huge page for less would be mostly unused.
// (640x480: the PNG's 0.9 MB of bytes take one, the 0.3 MB of surface flags not.)
constexpr std::size_t kHugeFrom = kHugePage / 4;

std::size_t huge_bytes(std::size_t bytes) {
    return (bytes + kHugePage - 1) / kHugePage * kHugePage;
}

} // namespace

void* allocate_huge(std::size_t bytes) {
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
}

void release_huge(void* p, std::size_t bytes) {
    if (!p) return;
    if (bytes < kHugeFrom)
        ::operator delete(p);
    else
        munmap(p, huge_bytes(bytes));
}

} // namespace seamless
