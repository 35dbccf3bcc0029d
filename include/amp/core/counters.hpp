#pragma once
#include <array>
#include <atomic>
#include <cstdint>

namespace amp::core {

// Phases of a run whose collision-detection cost is reported separately (UAS: training vs planning;
// every planner: the final query/smoothing).
enum class Phase : std::uint8_t { kTraining = 0, kPlanning = 1, kQuery = 2 };
inline constexpr int kPhaseCount = 3;

// Exact per-run cost counters. CD calls are the papers' cost measure, so every validity check is
// counted here; increments are relaxed atomics so several threads may share one run's counters.
class Counters {
 public:
  void set_phase(Phase p) noexcept { phase_.store(static_cast<std::uint8_t>(p), std::memory_order_relaxed); }
  Phase phase() const noexcept { return static_cast<Phase>(phase_.load(std::memory_order_relaxed)); }

  void add_cd_call() noexcept { cd_calls_[phase_.load(std::memory_order_relaxed)].fetch_add(1, std::memory_order_relaxed); }
  void add_clearance_call() noexcept { clearance_calls_.fetch_add(1, std::memory_order_relaxed); }
  void add_local_plan(bool success) noexcept {
    lp_calls_.fetch_add(1, std::memory_order_relaxed);
    if (success) lp_successes_.fetch_add(1, std::memory_order_relaxed);
  }
  void add_nn_query() noexcept { nn_queries_.fetch_add(1, std::memory_order_relaxed); }

  std::uint64_t cd_calls(Phase p) const noexcept { return cd_calls_[static_cast<int>(p)].load(std::memory_order_relaxed); }
  std::uint64_t cd_calls() const noexcept {
    std::uint64_t total = 0;
    for (const auto& c : cd_calls_) total += c.load(std::memory_order_relaxed);
    return total;
  }
  std::uint64_t clearance_calls() const noexcept { return clearance_calls_.load(std::memory_order_relaxed); }
  std::uint64_t lp_calls() const noexcept { return lp_calls_.load(std::memory_order_relaxed); }
  std::uint64_t lp_successes() const noexcept { return lp_successes_.load(std::memory_order_relaxed); }
  std::uint64_t nn_queries() const noexcept { return nn_queries_.load(std::memory_order_relaxed); }

 private:
  std::array<std::atomic<std::uint64_t>, kPhaseCount> cd_calls_{};
  std::atomic<std::uint64_t> clearance_calls_{0};
  std::atomic<std::uint64_t> lp_calls_{0};
  std::atomic<std::uint64_t> lp_successes_{0};
  std::atomic<std::uint64_t> nn_queries_{0};
  std::atomic<std::uint8_t> phase_{static_cast<std::uint8_t>(Phase::kPlanning)};
};

// Counts into `phase` for its lifetime and restores the phase it found, also when an exception
// leaves the scope.
class PhaseScope {
 public:
  PhaseScope(Counters& counters, Phase phase) noexcept : counters_(counters), saved_(counters.phase()) {
    counters_.set_phase(phase);
  }
  ~PhaseScope() { counters_.set_phase(saved_); }
  PhaseScope(const PhaseScope&) = delete;
  PhaseScope& operator=(const PhaseScope&) = delete;

 private:
  Counters& counters_;
  Phase saved_;
};

}  // namespace amp::core
