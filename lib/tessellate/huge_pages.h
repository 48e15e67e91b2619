// SPDX-License-Identifier: MIT
// Large output arrays backed by 2 MB pages where the system offers them
// (Linux transparent huge pages in "madvise" mode). A tessellation's arrays
// are written once, front to back; on 4 KB pages their first touch costs one
// page fault per 4 KB (teapot at D = 0.001: about 20,000 faults, a third of
// the run's CPU time in the kernel; docs/results/tessellation.md, sixth
// session i11h). Only the storage changes: the arrays, their values and the
// output are the same.
#pragma once

#include <cstddef>
#include <vector>

namespace seamless {

// Asks for 2 MB pages on the whole 2 MB pages inside [p, p + bytes) (nothing
// where the system has none, or the range holds none).
void advise_huge_pages(void* p, std::size_t bytes);

// Backs every 4 KB page of [p, p + bytes) for writing, 2 MB at a time on
// `threads` workers (parallel.h): the page faults of new storage are taken in
// parallel instead of on the thread that fills it (i11j), and, where Linux
// offers MADV_POPULATE_WRITE, by one call per 2 MB instead of a fault per
// page (contents unchanged); else by writing a zero byte into each page. For
// raw storage only (no live objects in it).
void touch_pages(void* p, std::size_t bytes, int threads);

// For a process that tessellates (the CLI, the benchmark's repetitions):
// asks glibc's malloc to keep the memory it frees (no trimming of the heap's
// top, no mmap below 32 MB, the most it allows), so that a later pass or call
// refills pages already touched instead of faulting in fresh ones. A process
// setting (mallopt): only a program's main calls it, never the library.
// Teapot --tolerance 0.001, AMD EPYC VM (~11 us per fault): the second pass
// re-faulted about 1,800 pages in the CLI; a warm repetition on one thread
// about 8,000 (i11o). Nothing where the C library is not glibc.
void keep_freed_memory();

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

} // namespace seamless
