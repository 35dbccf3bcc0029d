#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "amp/core/space.hpp"
#include "amp/core/stop_condition.hpp"
#include "amp/roadmap/local_planners/local_planner.hpp"
#include "amp/world/validity_checker.hpp"

namespace amp::roadmap {

// Checks the geodesic from a to b at the space's resolution: n = ceil(distance / resolution)
// segments (core::edge_segments, 64-bit), i.e. the n - 1 interior states at t = i / n, visited in
// bisection order (midpoint, then the quarter points, ...) as OMPL's DiscreteMotionValidator does,
// so that a blocked edge usually fails after a few CD calls. An edge whose n cannot be represented
// is refused. Counts one Counters::add_local_plan per call.
//
// `stop`, when given, is polled every core::StopPoll::kStride CD calls (time and cancel), counted
// across calls so that many short edges (smoothing, a lazy path check) are bounded as one long one
// is: once it fires the edge is refused, and so is every later one before its first CD call; the
// caller's own loop then sees the stop and reports it. A refused edge is never reported free.
class StraightLinePlanner final : public LocalPlanner {
 public:
  StraightLinePlanner(const core::Space& space, const world::ValidityChecker& checker,
                      const core::StopCondition* stop = nullptr);
  bool connect(const State& a, const State& b) override;

  // The interior step indices (1..n-1) of an n-segment edge in the order connect() checks them.
  // Exposed for tests; the returned reference is valid until the next call.
  const std::vector<int>& bisection_order(int segments);

  // Calls visit(i) (returning false to stop) for the interior steps of an n-segment edge in
  // bisection order, for any n up to core::kMaxEdgeSegments, in O(log n) memory: iterative
  // deepening over the interval tree, each level left to right, as a breadth-first queue would
  // (which holds n / 2 intervals). Returns false when visit stopped it.
  template <class Visit>
  static bool for_each_bisection_step(std::int64_t segments, Visit&& visit);

 private:
  // Edges of up to this many segments use a cached order (the order of repeated lengths is kept);
  // longer ones the generator, so that no edge allocates in proportion to its length.
  static constexpr std::int64_t kMaxCachedSegments = 1 << 16;
  // The largest block handed to a checker that checks several states at once.
  static constexpr std::size_t kMaxBlock = 8;

  bool check_in_blocks(const State& a, const State& b, const std::vector<int>& order, double inv);

  const core::Space* space_;
  const world::ValidityChecker* checker_;
  core::StopPoll poll_;
  // Scratch reused across calls: the order of the last segment count, and the interval queue.
  std::vector<int> order_;
  std::vector<std::pair<int, int>> queue_;
  int order_segments_ = -1;
  State scratch_;
  std::array<State, kMaxBlock> block_;
  std::array<const State*, kMaxBlock> block_refs_{};
};

template <class Visit>
bool StraightLinePlanner::for_each_bisection_step(std::int64_t segments, Visit&& visit) {
  struct Interval {
    std::int64_t lo, hi;
    int depth;
  };
  // The tree of a 2^63-step edge is 63 levels deep; a depth-first walk holds at most one pending
  // right half per level plus the current interval.
  std::array<Interval, 66> stack;
  if (segments < 2) return true;
  for (int level = 0;; ++level) {
    bool reached = false;
    std::size_t top = 0;
    stack[top++] = {1, segments - 1, 0};
    while (top > 0) {
      const Interval iv = stack[--top];
      const std::int64_t mid = iv.lo + (iv.hi - iv.lo) / 2;
      if (iv.depth == level) {
        reached = true;
        if (!visit(mid)) return false;
        continue;
      }
      if (mid < iv.hi) stack[top++] = {mid + 1, iv.hi, iv.depth + 1};  // pushed first: popped after the left
      if (iv.lo < mid) stack[top++] = {iv.lo, mid - 1, iv.depth + 1};
    }
    if (!reached) return true;
  }
}

}  // namespace amp::roadmap
