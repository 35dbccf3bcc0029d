#include "amp/roadmap/disjoint_sets.hpp"

#include <numeric>
#include <utility>

namespace amp::roadmap {

void DisjointSets::reserve(std::size_t n) {
  parent_.reserve(n);
  rank_.reserve(n);
}

std::size_t DisjointSets::add() {
  parent_.push_back(parent_.size());
  rank_.push_back(0);
  ++sets_;
  return parent_.size() - 1;
}

std::size_t DisjointSets::find(std::size_t x) const {
  while (parent_[x] != x) {
    parent_[x] = parent_[parent_[x]];  // path halving
    x = parent_[x];
  }
  return x;
}

bool DisjointSets::unite(std::size_t a, std::size_t b) {
  a = find(a);
  b = find(b);
  if (a == b) return false;
  if (rank_[a] < rank_[b]) std::swap(a, b);
  parent_[b] = a;
  if (rank_[a] == rank_[b]) ++rank_[a];
  --sets_;
  return true;
}

void DisjointSets::reset() {
  std::iota(parent_.begin(), parent_.end(), std::size_t{0});
  std::fill(rank_.begin(), rank_.end(), std::uint8_t{0});
  sets_ = parent_.size();
}

}  // namespace amp::roadmap
