// SPDX-License-Identifier: MIT
// Union-find over 0..n-1 with path halving; each set is represented by its
// smallest element, so numbering sets by their first member is deterministic.
#pragma once

#include <algorithm>
#include <numeric>
#include <vector>

namespace seamless {

struct DisjointSets {
    std::vector<int> parent;
    explicit DisjointSets(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
    int find(int x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    }
    void unite(int a, int b) {
        a = find(a), b = find(b);
        if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
};

} // namespace seamless
