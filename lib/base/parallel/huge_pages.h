// SPDX-License-Identifier: MIT
// Large arrays written once, front to back (a tessellation's outputs, the
// image's pixels, the light planes, the PNG's bytes), backed by 2 MB pages
// where the system offers them (Linux transparent huge pages in "madvise"
// mode): on 4 KB pages their first touch costs one page fault per 4 KB, a
// large share of a tessellation's or a render's CPU time
// (docs/results/tessellation.md, docs/results/render.md). Only the storage
// changes: the arrays, their values and the output are the same. Where the
// kernel has no huge page free, 4 KB pages serve.
#pragma once

#include <cstddef>
#include <memory>
#include <type_traits>
#include <vector>

namespace seamless {

// --- Raw storage, none of it constructed ------------------------------------

// From 512 KB up: 2 MB-aligned anonymous mmap advised MADV_HUGEPAGE; below,
// operator new (a huge page for less would be mostly unused).
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

// --- std::vector storage ----------------------------------------------------

// Asks for 2 MB pages on the whole 2 MB pages inside [p, p + bytes) (nothing
// where the system has none, or the range holds none).
void advise_huge_pages(void* p, std::size_t bytes);

// Backs every 4 KB page of [p, p + bytes) for writing, 2 MB at a time on
// `threads` workers (parallel.h): the page faults of new storage are taken in
// parallel instead of on the thread that fills it, and, where Linux offers
// MADV_POPULATE_WRITE, by one call per 2 MB instead of a fault per page
// (contents unchanged); else by writing a zero byte into each page. For raw
// storage only (no live objects in it).
void touch_pages(void* p, std::size_t bytes, int threads);

// v.reserve(n) with the new storage advised for 2 MB pages before anything
// is written to it (v's elements are copied in after the advice); a resize to
// at most n then touches it. The new storage is first backed by `threads`
// workers (touch_pages).
template <class T> void reserve_huge(std::vector<T>& v, std::size_t n, int threads = 1) {
    if (n <= v.capacity()) return;
    std::vector<T> w;
    w.reserve(n);
    advise_huge_pages(w.data(), w.capacity() * sizeof(T));
    touch_pages(w.data(), w.capacity() * sizeof(T), threads);
    w.insert(w.end(), v.begin(), v.end());
    v.swap(w);
}

// --- The process's heap -----------------------------------------------------

// For a process that tessellates or renders more than once (the CLI, the
// benchmarks' repetitions): asks glibc's malloc to keep the memory it frees
// (no trimming of the heap's top, no mmap below 32 MB, the most it allows), so
// that a later pass or call refills pages already touched instead of faulting
// in fresh ones. A process setting (mallopt): only a program's main calls it,
// never the library. Nothing where the C library is not glibc.
void keep_freed_memory();

} // namespace seamless
