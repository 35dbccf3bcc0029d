#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace amp::roadmap {

// Union-find over 0..n-1 with path halving and union by rank (Tarjan 1975): near-constant time per
// operation, so a planner may ask "same component?" for every candidate edge.
class DisjointSets {
 public:
  void reserve(std::size_t n);
  // Adds a singleton set and returns its element.
  std::size_t add();
  // Representative of x's set. Compresses paths, which changes no observable answer, hence const.
  std::size_t find(std::size_t x) const;
  // Joins the sets of a and b; returns false when they were already one set.
  bool unite(std::size_t a, std::size_t b);
  bool same(std::size_t a, std::size_t b) const { return find(a) == find(b); }
  std::size_t size() const { return parent_.size(); }
  std::size_t set_count() const { return sets_; }
  // Back to singletons (n elements kept).
  void reset();

 private:
  mutable std::vector<std::size_t> parent_;
  std::vector<std::uint8_t> rank_;
  std::size_t sets_ = 0;
};

}  // namespace amp::roadmap
