#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace amp::roadmap {

// The cells one grid search has reached, each with a dense id in the order of insertion: an
// open-addressing hash table (linear probing, at most half full) that clear() empties in O(1) by a
// generation stamp, because PRM-C/G/L run thousands of short searches and each reaches few cells.
// Slots and cells are kept between searches, so a search allocates only when it outgrows them.
class GridCellTable {
 public:
  static constexpr int kMaxDims = 12;
  using Cell = std::array<std::int16_t, kMaxDims>;  // coordinates past dims() are 0

  // `dims` in [1, kMaxDims] (the caller checks); `slots` a power of two.
  explicit GridCellTable(int dims, std::size_t slots = 1024);

  void clear();
  // The id of c, or -1 when it has not been inserted since clear().
  std::int32_t find(const Cell& c) const;
  // Inserts c, which must not be present, and returns its id (the number of cells before it).
  std::int32_t insert(const Cell& c);
  std::size_t size() const { return cells_.size(); }
  std::size_t slots() const { return slots_.size(); }

 private:
  struct Slot {
    std::int32_t id = -1;
    std::uint32_t generation = 0;
  };
  std::uint64_t hash(const Cell& c) const;
  void place(std::int32_t id);
  void grow();  // twice the slots, this search's cells rehashed in id order

  int dims_;
  std::vector<Cell> cells_;
  std::vector<Slot> slots_;
  std::uint32_t generation_ = 1;  // slots stamped with another generation are empty
};

}  // namespace amp::roadmap
