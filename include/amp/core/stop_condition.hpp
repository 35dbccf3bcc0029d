#pragma once
#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>

namespace amp::core {

// Where a StopCondition reads the time, when not from the steady clock: seconds since the run began.
// Tests give a clock that advances per read, so that a run trips after a known number of polls
// however busy the machine is (tests/roadmap/stop_mechanism_test.cpp).
class TimeSource {
 public:
  virtual ~TimeSource() = default;
  virtual double seconds_since_start() const = 0;
};

// Why a planner was told to stop. Checked once per planner iteration, so it must be cheap.
enum class StopReason { kNone, kTimeLimit, kNodeLimit, kCancelled };

// Time limit + node limit + external cancel flag (Ctrl-C in `amp bench`). check() reads the clock on
// every call (~40 ns): a stride over calls cannot bound the time between reads, as one planner
// iteration may take seconds. Work that is long inside one iteration (the states of one edge, the
// cells of one A* search) polls time_up() every few hundred steps (StopPoll below).
// One run, one thread: the latch below is not synchronised.
class StopCondition {
 public:
  using Clock = std::chrono::steady_clock;

  StopCondition(double time_limit_s, std::size_t node_limit, const std::atomic<bool>* cancel = nullptr);
  // The same, reading the time from `clock` (which must outlive the condition) instead.
  StopCondition(double time_limit_s, std::size_t node_limit, const TimeSource& clock);

  // True when the planner must stop; `nodes` is the planner's current roadmap size.
  StopReason check(std::size_t nodes) const;
  bool should_stop(std::size_t nodes) const { return check(nodes) != StopReason::kNone; }

  // Cancelled or past the deadline (reads the clock), for loops that do not know the node count.
  // Once true it stays true, and check() then reports kTimeLimit (or kCancelled) at once.
  bool time_up() const;
  // Whether time_up() or check() has already seen the deadline, or the run is cancelled: no clock
  // read, for a caller about to start work that the stop would abandon anyway.
  bool fired() const { return timed_out_ || cancelled(); }

  double elapsed_seconds() const;
  double time_limit() const { return time_limit_s_; }
  std::size_t node_limit() const { return node_limit_; }

 private:
  bool cancelled() const { return cancel_ != nullptr && cancel_->load(std::memory_order_relaxed); }

  Clock::time_point start_;
  Clock::time_point deadline_;
  double time_limit_s_;
  std::size_t node_limit_;
  const std::atomic<bool>* cancel_;
  const TimeSource* clock_ = nullptr;  // null: the steady clock
  mutable bool timed_out_ = false;
};

// Polls an optional StopCondition every kStride steps of a long loop (a CD call each). Measured:
// a clock read costs ~40 ns, a CD call 0.05 us (planar point robot) to 35 us (the 6-DOF puzzle's
// grid A* cells), so 256 steps keep the read under 0.3 % of the cheapest loop and the delay past
// the deadline under 10 ms for the dearest (4096 let the puzzle run 140 ms over). A null
// condition never fires.
class StopPoll {
 public:
  static constexpr std::uint32_t kStride = 256;

  explicit StopPoll(const StopCondition* stop) : stop_(stop) {}
  // At the start of the work: a stop seen before refuses it without a step.
  bool fired() {
    stopped_ = stopped_ || (stop_ != nullptr && stop_->fired());
    return stopped_;
  }
  // Once per step: true when the work must be abandoned, and on every step after that.
  bool step() {
    if (stopped_) return true;
    if (stop_ == nullptr || ++steps_ < kStride) return false;
    steps_ = 0;
    stopped_ = stop_->time_up();
    return stopped_;
  }

 private:
  const StopCondition* stop_;
  std::uint32_t steps_ = 0;
  bool stopped_ = false;
};

}  // namespace amp::core
