#include "amp/roadmap/straight_line_planner.hpp"

#include <algorithm>
#include <cmath>

namespace amp::roadmap {

StraightLinePlanner::StraightLinePlanner(const core::Space& space, const world::ValidityChecker& checker)
    : space_(&space), checker_(&checker) {}

const std::vector<int>& StraightLinePlanner::bisection_order(int segments) {
  if (segments == order_segments_) return order_;
  order_.clear();
  queue_.clear();
  // Breadth-first over intervals of unchecked steps [lo, hi]: each visit checks the middle step
  // and queues the two halves (OMPL DiscreteMotionValidator::checkMotion).
  if (segments >= 2) queue_.emplace_back(1, segments - 1);
  for (std::size_t head = 0; head < queue_.size(); ++head) {
    const auto [lo, hi] = queue_[head];
    const int mid = lo + (hi - lo) / 2;
    order_.push_back(mid);
    if (lo < mid) queue_.emplace_back(lo, mid - 1);
    if (mid < hi) queue_.emplace_back(mid + 1, hi);
  }
  order_segments_ = segments;
  return order_;
}

bool StraightLinePlanner::connect(const State& a, const State& b) {
  const double d = space_->distance(a, b);
  const int segments = std::max(1, static_cast<int>(std::ceil(d / space_->resolution())));
  const std::vector<int>& order = bisection_order(segments);
  const double inv = 1.0 / segments;
  bool free = true;
  for (const int step : order) {
    space_->interpolate(a, b, step * inv, scratch_);
    if (!checker_->is_valid(scratch_)) {
      free = false;
      break;
    }
  }
  checker_->counters().add_local_plan(free);
  return free;
}

}  // namespace amp::roadmap
