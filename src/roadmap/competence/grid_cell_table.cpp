#include "amp/roadmap/competence/grid_cell_table.hpp"

namespace amp::roadmap {

GridCellTable::GridCellTable(int dims, std::size_t slots) : dims_(dims), slots_(slots) {}

void GridCellTable::clear() {
  cells_.clear();
  if (++generation_ == 0) {  // wrapped: clear the stamps once every 2^32 searches
    slots_.assign(slots_.size(), Slot{});
    generation_ = 1;
  }
}

std::uint64_t GridCellTable::hash(const Cell& c) const {
  std::uint64_t h = 0x9e3779b97f4a7c15ULL;
  for (int i = 0; i < dims_; ++i) {
    h ^= static_cast<std::uint16_t>(c[static_cast<std::size_t>(i)]);
    h *= 0xff51afd7ed558ccdULL;
    h ^= h >> 29;
  }
  return h;
}

std::int32_t GridCellTable::find(const Cell& c) const {
  const std::size_t mask = slots_.size() - 1;
  for (std::size_t i = hash(c) & mask;; i = (i + 1) & mask) {
    const Slot& s = slots_[i];
    if (s.generation != generation_) return -1;
    if (cells_[static_cast<std::size_t>(s.id)] == c) return s.id;
  }
}

std::int32_t GridCellTable::insert(const Cell& c) {
  if (2 * (cells_.size() + 1) > slots_.size()) grow();
  const auto id = static_cast<std::int32_t>(cells_.size());
  cells_.push_back(c);
  place(id);
  return id;
}

void GridCellTable::place(std::int32_t id) {
  const std::size_t mask = slots_.size() - 1;
  std::size_t i = hash(cells_[static_cast<std::size_t>(id)]) & mask;
  while (slots_[i].generation == generation_) i = (i + 1) & mask;
  slots_[i] = Slot{id, generation_};
}

void GridCellTable::grow() {
  // Amortised like vector growth; the stamps restart, as every slot is new.
  slots_.assign(slots_.size() * 2, Slot{});
  generation_ = 1;
  for (std::size_t id = 0; id < cells_.size(); ++id) place(static_cast<std::int32_t>(id));
}

}  // namespace amp::roadmap
