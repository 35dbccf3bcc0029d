#include "amp/core/stop_condition.hpp"

#include <algorithm>
#include <cmath>

namespace amp::core {

namespace {
// Longest limit honoured as given (~31 years); longer or infinite limits mean "no time limit" and
// must not overflow the clock's representation.
constexpr double kMaxTimeLimitSeconds = 1e9;
}  // namespace

StopCondition::StopCondition(double time_limit_s, std::size_t node_limit, const std::atomic<bool>* cancel)
    : start_(Clock::now()), time_limit_s_(time_limit_s), node_limit_(node_limit), cancel_(cancel) {
  const double capped = std::isfinite(time_limit_s) ? std::clamp(time_limit_s, 0.0, kMaxTimeLimitSeconds)
                                                    : kMaxTimeLimitSeconds;
  deadline_ = start_ + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(capped));
}

StopCondition::StopCondition(double time_limit_s, std::size_t node_limit, const TimeSource& clock)
    : StopCondition(time_limit_s, node_limit) {
  clock_ = &clock;
}

StopReason StopCondition::check(std::size_t nodes) const {
  if (cancelled()) return StopReason::kCancelled;
  if (nodes >= node_limit_) return StopReason::kNodeLimit;
  return time_up() ? StopReason::kTimeLimit : StopReason::kNone;
}

bool StopCondition::time_up() const {
  if (cancelled()) return true;
  if (timed_out_) return true;
  timed_out_ = clock_ != nullptr ? clock_->seconds_since_start() >= time_limit_s_ : Clock::now() >= deadline_;
  return timed_out_;
}

double StopCondition::elapsed_seconds() const {
  if (clock_ != nullptr) return clock_->seconds_since_start();
  return std::chrono::duration<double>(Clock::now() - start_).count();
}

}  // namespace amp::core
