// SPDX-License-Identifier: MIT
// Fresh storage for an array the calling thread sizes and workers fill: its
// pages backed by `threads` workers before anything is written. A resize of
// fresh storage takes its page faults on the calling thread alone, while the
// other worker waits (a worker's freed memory stays in that worker's malloc
// arena, so the calling thread seldom reuses it).
// Only the storage changes: the arrays and the output are the same.
#pragma once

#include <seamless/base/parallel/huge_pages.h>
#include <seamless/base/parallel/parallel.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace seamless {

// v.reserve(n), its new storage backed by `threads` workers: from 2 MB up by
// reserve_huge (2 MB pages where offered, one worker per 2 MB), below in
// pieces of 64 KB, so that an array under 2 MB is shared among the workers.
template <class T> void reserve_touched(std::vector<T>& v, std::size_t n, int threads) {
    constexpr std::size_t kHuge = std::size_t{2} << 20, kPiece = std::size_t{64} << 10;
    if (n <= v.capacity()) return;
    if (threads == 1 || n * sizeof(T) >= kHuge) {
        reserve_huge(v, n, threads);
        return;
    }
    std::vector<T> w;
    w.reserve(n);
    char* const p = reinterpret_cast<char*>(w.data());
    const std::size_t bytes = w.capacity() * sizeof(T);
    parallel_chunks(static_cast<int>((bytes + kPiece - 1) / kPiece), threads,
                    [&](int begin, int end) {
                        const std::size_t from = begin * kPiece;
                        touch_pages(p + from, std::min(bytes, end * kPiece) - from, 1);
                    });
    w.insert(w.end(), v.begin(), v.end());
    v.swap(w);
}

// v.assign(n, value) on storage from reserve_touched.
template <class T>
void assign_touched(std::vector<T>& v, std::size_t n, const T& value, int threads) {
    reserve_touched(v, n, threads);
    v.assign(n, value);
}

} // namespace seamless
