#pragma once
#include <cstddef>
#include <utility>
#include <vector>

#include "amp/core/space.hpp"
#include "amp/roadmap/local_planner.hpp"
#include "amp/world/validity_checker.hpp"

namespace amp::roadmap {

// Checks the geodesic from a to b at the space's resolution: n = ceil(distance / resolution)
// segments, i.e. the n - 1 interior states at t = i / n, visited in bisection order (midpoint, then
// the quarter points, ...) as OMPL's DiscreteMotionValidator does, so that a blocked edge usually
// fails after a few CD calls. Counts one Counters::add_local_plan per call.
class StraightLinePlanner final : public LocalPlanner {
 public:
  StraightLinePlanner(const core::Space& space, const world::ValidityChecker& checker);
  bool connect(const State& a, const State& b) override;

  // The interior step indices (1..n-1) of an n-segment edge in the order connect() checks them.
  // Exposed for tests; the returned reference is valid until the next call.
  const std::vector<int>& bisection_order(int segments);

 private:
  const core::Space* space_;
  const world::ValidityChecker* checker_;
  // Scratch reused across calls: the order of the last segment count, and the interval queue.
  std::vector<int> order_;
  std::vector<std::pair<int, int>> queue_;
  int order_segments_ = -1;
  State scratch_;
};

}  // namespace amp::roadmap
