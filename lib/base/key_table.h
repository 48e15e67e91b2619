// SPDX-License-Identifier: MIT
// What a pass of a tolerance keeps per subpatch for the next (the
// subdivision's verdicts, the certified bounds; tessellation_pass.h), by subpatch_key:
// open addressing over one flat array, linear probing, at most half full and
// doubled when it would be more. One allocation per doubling instead of a heap
// node per key (tens of thousands of keys, allocated in the passes and freed
// one by one at the end).
#pragma once

#include <seamless/base/first_met.h>
#include <seamless/base/parallel/cache_line.h>

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace seamless {

// On a cache line of its own: one table per patch, filled by the workers
// side by side (cache_line.h).
template <class Value> class alignas(kCacheLine) KeyTable {
  public:
    // The value stored with `key`, or null.
    const Value* find(std::uint64_t key) const {
        if (slots_.empty()) return nullptr;
        for (std::size_t h = MixHash{}(key)&mask_;; h = (h + 1) & mask_) {
            const Slot& s = slots_[h];
            if (!s.used) return nullptr;
            if (s.key == key) return &s.value;
        }
    }
    // The value stored with `key`, value-initialised when the key is new.
    Value& operator[](std::uint64_t key) {
        if (2 * (count_ + 1) > slots_.size()) grow();
        for (std::size_t h = MixHash{}(key)&mask_;; h = (h + 1) & mask_) {
            Slot& s = slots_[h];
            if (!s.used) {
                s.used = true;
                s.key = key;
                ++count_;
                return s.value;
            }
            if (s.key == key) return s.value;
        }
    }
    std::size_t size() const { return count_; }
    // Room for n keys in all: no doubling (and no rehashing) up to them.
    void reserve(std::size_t n) {
        std::size_t size = slots_.empty() ? 64 : slots_.size();
        while (size < 2 * n) size *= 2;
        if (size > slots_.size()) rehash(size);
    }

  private:
    struct Slot {
        std::uint64_t key = 0;
        Value value{};
        bool used = false;
    };
    void grow() { rehash(slots_.empty() ? 64 : 2 * slots_.size()); }
    void rehash(std::size_t size) {
        std::vector<Slot> old(size);
        old.swap(slots_);
        mask_ = slots_.size() - 1;
        count_ = 0;
        for (Slot& s : old)
            if (s.used) (*this)[s.key] = std::move(s.value);
    }
    std::vector<Slot> slots_;
    std::size_t mask_ = 0;
    std::size_t count_ = 0;
};

} // namespace seamless
