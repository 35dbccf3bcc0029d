#include "amp/core/stop_condition.hpp"

#include <cmath>
#include <limits>

namespace amp::core {

namespace {
// Reading steady_clock costs ~20 ns; planners call check() per sample, so sample the clock sparsely.
constexpr unsigned kClockStride = 8;
}  // namespace

StopCondition::StopCondition(double time_limit_s, std::size_t node_limit, const std::atomic<bool>* cancel)
    : start_(Clock::now()), time_limit_s_(time_limit_s), node_limit_(node_limit), cancel_(cancel) {
  const double capped = std::isfinite(time_limit_s) ? std::min(time_limit_s, 1e9) : 1e9;
  deadline_ = start_ + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(capped));
}

StopReason StopCondition::check(std::size_t nodes) const {
  if (cancel_ != nullptr && cancel_->load(std::memory_order_relaxed)) return StopReason::kCancelled;
  if (nodes >= node_limit_) return StopReason::kNodeLimit;
  if (timed_out_) return StopReason::kTimeLimit;
  if (++calls_ % kClockStride == 0 || calls_ == 1) {
    if (Clock::now() >= deadline_) {
      timed_out_ = true;
      return StopReason::kTimeLimit;
    }
  }
  return StopReason::kNone;
}

double StopCondition::elapsed_seconds() const {
  return std::chrono::duration<double>(Clock::now() - start_).count();
}

}  // namespace amp::core
