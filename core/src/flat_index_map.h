// A hash map from 64-bit keys to ints for the flat refinement (flat_patch.h) and the cells that
// mesh_face_index.cpp marks: open addressing with linear probing in one array, no erase (a count
// that falls to 0 stays as an entry). Written here because std::unordered_map's node per entry
// cost more than the rest of a split, and Debian 12's hash-map libraries (abseil) would be a
// dependency for these few lines.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace holefill::detail {

class FlatIndexMap {
 public:
  // Room for about `expected` keys before the first growth.
  explicit FlatIndexMap(std::size_t expected = 8) { rehash(capacity_for(expected)); }

  // The value stored for `key`, or `absent` when there is none.
  int find(std::uint64_t key, int absent) const {
    for (std::size_t slot = home(key);; slot = (slot + 1) & mask_) {
      if (slots_[slot].key == key) return slots_[slot].value;
      if (slots_[slot].key == kEmpty) return absent;
    }
  }

  // The value stored for `key`, stored as `initial` first when there is none. The reference
  // stays valid until the next call.
  int& find_or_insert(std::uint64_t key, int initial) {
    if (2 * (used_ + 1) > slots_.size()) rehash(2 * slots_.size());
    std::size_t slot = home(key);
    while (slots_[slot].key != key && slots_[slot].key != kEmpty) slot = (slot + 1) & mask_;
    if (slots_[slot].key == kEmpty) {
      slots_[slot] = {key, initial};
      ++used_;
    }
    return slots_[slot].value;
  }

 private:
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};  // never a key (see callers)
  struct Slot {
    std::uint64_t key = kEmpty;
    int value = 0;
  };

  static std::size_t capacity_for(std::size_t expected) {
    std::size_t capacity = 16;
    while (capacity < 2 * expected) capacity *= 2;
    return capacity;
  }

  // Fibonacci hashing: the top bits of the key times 2^64 / phi.
  std::size_t home(std::uint64_t key) const {
    return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> shift_);
  }

  void rehash(std::size_t capacity) {
    std::vector<Slot> old(capacity);
    old.swap(slots_);
    mask_ = capacity - 1;
    shift_ = 64;
    for (std::size_t c = capacity; c > 1; c /= 2) --shift_;
    used_ = 0;
    for (const Slot& s : old) {
      if (s.key != kEmpty) find_or_insert(s.key, s.value);
    }
  }

  std::vector<Slot> slots_;
  std::size_t mask_ = 0;
  int shift_ = 64;
  std::size_t used_ = 0;
};

}  // namespace holefill::detail
