#pragma once
#include <vector>

#include "amp/core/counters.hpp"
#include "amp/core/space.hpp"
#include "amp/roadmap/neighbors/nearest_neighbors.hpp"

namespace amp::roadmap {

// Brute force: O(n) per query. The reference the KD-tree is tested against, and the faster choice
// for a few hundred states (a training roadmap, one component's members).
class LinearNeighbors final : public NearestNeighbors {
 public:
  // `counters` may be null (no counting); both must outlive this object.
  explicit LinearNeighbors(const core::Space& space, core::Counters* counters = nullptr)
      : space_(&space), counters_(counters) {}

  void add(std::size_t index, const State& s) override;
  void k_nearest(const State& q, std::size_t k, std::vector<Neighbor>& out) const override;
  std::size_t size() const override { return states_.size(); }
  void reserve(std::size_t n) override;

 private:
  const core::Space* space_;
  core::Counters* counters_;
  std::vector<State> states_;
  std::vector<std::size_t> indices_;
};

}  // namespace amp::roadmap
