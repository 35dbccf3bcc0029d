#pragma once
#include <atomic>
#include <chrono>
#include <cstddef>

namespace amp::core {

// Why a planner was told to stop. Checked once per planner iteration, so it must be cheap.
enum class StopReason { kNone, kTimeLimit, kNodeLimit, kCancelled };

// Time limit + node limit + external cancel flag (Ctrl-C in `amp bench`). The clock is read only
// every few calls to keep the check cheap in tight loops.
class StopCondition {
 public:
  using Clock = std::chrono::steady_clock;

  StopCondition(double time_limit_s, std::size_t node_limit, const std::atomic<bool>* cancel = nullptr);

  // True when the planner must stop; `nodes` is the planner's current roadmap size.
  StopReason check(std::size_t nodes) const;
  bool should_stop(std::size_t nodes) const { return check(nodes) != StopReason::kNone; }

  double elapsed_seconds() const;
  double time_limit() const { return time_limit_s_; }
  std::size_t node_limit() const { return node_limit_; }

 private:
  Clock::time_point start_;
  Clock::time_point deadline_;
  double time_limit_s_;
  std::size_t node_limit_;
  const std::atomic<bool>* cancel_;
  mutable unsigned calls_ = 0;
  mutable bool timed_out_ = false;
};

}  // namespace amp::core
