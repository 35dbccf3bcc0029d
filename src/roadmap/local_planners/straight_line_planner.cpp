#include "amp/roadmap/local_planners/straight_line_planner.hpp"

#include <algorithm>

#include "amp/core/edge_steps.hpp"

namespace amp::roadmap {

StraightLinePlanner::StraightLinePlanner(const core::Space& space, const world::ValidityChecker& checker,
                                         const core::StopCondition* stop)
    : space_(&space), checker_(&checker), poll_(stop) {}

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
  const std::int64_t segments = core::edge_segments(space_->distance(a, b), space_->resolution());
  bool free = segments > 0 && !poll_.fired();
  if (free) {
    const double inv = 1.0 / static_cast<double>(segments);
    const auto check = [&](std::int64_t step) {
      space_->interpolate(a, b, static_cast<double>(step) * inv, scratch_);
      free = !poll_.step() && checker_->is_valid(scratch_);
      return free;
    };
    if (checker_->block_size() > 1 && segments <= kMaxCachedSegments) {
      free = check_in_blocks(a, b, bisection_order(static_cast<int>(segments)), inv);
    } else if (segments <= kMaxCachedSegments) {
      for (const int step : bisection_order(static_cast<int>(segments))) {
        if (!check(step)) break;
      }
    } else {
      for_each_bisection_step(segments, check);
    }
  }
  checker_->counters().add_local_plan(free);
  return free;
}

// The same steps in the same order, a block of the checker's size at a time: a blocked edge may
// cost up to a block's CD calls more, and every block is posed at once.
bool StraightLinePlanner::check_in_blocks(const State& a, const State& b, const std::vector<int>& order, double inv) {
  const std::size_t size = std::min(checker_->block_size(), kMaxBlock);
  for (std::size_t first = 0; first < order.size(); first += size) {
    const std::size_t n = std::min(size, order.size() - first);
    for (std::size_t i = 0; i < n; ++i) {
      if (poll_.step()) return false;
      space_->interpolate(a, b, static_cast<double>(order[first + i]) * inv, block_[i]);
      block_refs_[i] = &block_[i];
    }
    if (!checker_->all_valid(block_refs_.data(), n)) return false;
  }
  return true;
}

}  // namespace amp::roadmap
