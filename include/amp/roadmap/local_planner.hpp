#pragma once
#include "amp/core/state.hpp"

namespace amp::roadmap {

// Decides whether two configurations can be joined by the planner's path between them; the
// endpoints are assumed valid. Implementations: StraightLinePlanner (later an A* grid planner).
// Holds per-thread scratch (hence non-const connect); use one per thread.
class LocalPlanner {
 public:
  virtual ~LocalPlanner() = default;
  virtual bool connect(const State& a, const State& b) = 0;
};

}  // namespace amp::roadmap
