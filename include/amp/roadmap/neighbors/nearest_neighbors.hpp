#pragma once
#include <cstddef>
#include <vector>

#include "amp/core/state.hpp"

namespace amp::roadmap {

struct Neighbor {
  std::size_t index = 0;  // the index given to add()
  double distance = 0.0;  // core::Space::distance to the query

  // Sorted by distance, ties by index, so that every implementation returns the same list.
  friend bool operator<(const Neighbor& a, const Neighbor& b) {
    return a.distance < b.distance || (a.distance == b.distance && a.index < b.index);
  }
  friend bool operator==(const Neighbor& a, const Neighbor& b) = default;
};

// Exact k-nearest-neighbour search under a space's metric. Implementations: LinearNeighbors (brute
// force, the reference) and KdTreeNeighbors (dynamic KD-tree, exact by lower bounds). Each query counts one
// Counters::add_nn_query when the implementation was given counters.
class NearestNeighbors {
 public:
  virtual ~NearestNeighbors() = default;

  // Adds a state under a caller-chosen index (e.g. a roadmap vertex); indices need not be dense.
  virtual void add(std::size_t index, const State& s) = 0;
  // The min(k, size()) stored states nearest to q, sorted by (distance, index), into `out` (cleared
  // first; its capacity is reused, so a caller's buffer makes the query allocation-free).
  virtual void k_nearest(const State& q, std::size_t k, std::vector<Neighbor>& out) const = 0;
  virtual std::size_t size() const = 0;
  // Room for n states (planners reserve to their node budget).
  virtual void reserve(std::size_t /*n*/) {}
};

}  // namespace amp::roadmap
