#include "amp/roadmap/neighbors/linear_neighbors.hpp"

#include <algorithm>

namespace amp::roadmap {

void LinearNeighbors::add(std::size_t index, const State& s) {
  states_.push_back(s);
  indices_.push_back(index);
}

void LinearNeighbors::reserve(std::size_t n) {
  states_.reserve(n);
  indices_.reserve(n);
}

void LinearNeighbors::k_nearest(const State& q, std::size_t k, std::vector<Neighbor>& out) const {
  if (counters_ != nullptr) counters_->add_nn_query();
  out.clear();
  k = std::min(k, states_.size());
  if (k == 0) return;
  // Keep the k best seen so far as a sorted list: O(n k) worst case, but k is small (<= ~50) and
  // the list rarely changes after the first few hundred states.
  for (std::size_t i = 0; i < states_.size(); ++i) {
    const Neighbor n{indices_[i], space_->distance(q, states_[i])};
    if (out.size() == k) {
      if (!(n < out.back())) continue;
      out.pop_back();
    }
    out.insert(std::upper_bound(out.begin(), out.end(), n), n);
  }
}

}  // namespace amp::roadmap
