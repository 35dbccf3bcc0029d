// How a planner honours its time limit, tested without a wall clock (issue 34): the run's
// StopCondition reads a clock whose time is the work done so far (one microsecond per CD or
// clearance call). Every run is then deterministic, whatever the machine's load, and two things
// are checked for every planner on a sealed goal (never solved, so only the limit ends the run):
// the planner notices the limit within a bounded amount of work past it (it polls often enough,
// also inside an edge of millions of steps), and stops within a bounded amount of work after it
// noticed. The wall-clock promise itself is the `timing` label's (run_limits_test.cpp).
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "amp/core/counters.hpp"
#include "amp/core/rng.hpp"
#include "amp/core/stop_condition.hpp"
#include "amp/roadmap/catalog/planner_registry.hpp"
#include "amp/world/problem.hpp"
#include "support/planner_runs.hpp"
#include "support/source_tree.hpp"

namespace amp::roadmap {
namespace {

namespace fs = std::filesystem;

const fs::path kSealed = fs::path(AMP_SOURCE_DIR) / "tests" / "apps" / "data" / "sealed.yaml";
constexpr double kSecondsPerCall = 1e-6;
constexpr double kTimeLimit = 0.02;  // 20,000 calls of work
constexpr std::size_t kNoNodeLimit = static_cast<std::size_t>(-1);
// Work allowed between passing the limit and noticing it, and between noticing it and returning.
// StopPoll reads the clock every 256 steps of a long loop; one planner iteration outside such a
// loop (a sample and its few edges at the default resolution) costs a few hundred calls.
constexpr std::uint64_t kNoticeCalls = 4 * core::StopPoll::kStride;
constexpr std::uint64_t kAfterCalls = 4 * core::StopPoll::kStride;

// Time = the run's work; remembers the work done when a read first reported the limit reached.
class WorkClock : public core::TimeSource {
 public:
  WorkClock(const core::Counters& counters, double limit_s) : counters_(counters), limit_s_(limit_s) {}
  double seconds_since_start() const override {
    const std::uint64_t calls = work();
    const double t = kSecondsPerCall * static_cast<double>(calls);
    if (t >= limit_s_ && noticed_at_ == 0) noticed_at_ = calls;
    return t;
  }
  std::uint64_t work() const { return counters_.cd_calls() + counters_.clearance_calls(); }
  std::uint64_t noticed_at() const { return noticed_at_; }

 private:
  const core::Counters& counters_;
  double limit_s_;
  mutable std::uint64_t noticed_at_ = 0;
};

struct Outcome {
  core::PlanStatus status = core::PlanStatus::kError;
  std::uint64_t noticed_at = 0;
  std::uint64_t work = 0;
  std::uint64_t nodes = 0;
};

Outcome run_on_work_clock(const world::Problem& p, const std::string& planner, std::uint64_t seed) {
  core::Counters counters;
  counters.set_phase(core::Phase::kPlanning);
  const auto checker = p.environment->make_checker(counters);
  const WorkClock clock(counters, kTimeLimit);
  const core::StopCondition stop(kTimeLimit, kNoNodeLimit, clock);
  const auto made = builtin_planners().make(planner, {});
  const PlanningContext ctx{*p.space, *p.environment, *checker, p.seeds, p.defaults.edge_check, &stop};
  core::Rng rng(seed);
  const PlanResult r = made->plan(ctx, stop, rng);
  return {r.status, clock.noticed_at(), clock.work(), r.nodes};
}

world::Problem sealed_at(const std::string& resolution) {
  if (resolution.empty()) return world::load_problem(kSealed);
  const fs::path file = fs::temp_directory_path() / ("amp_stop_mechanism_" + std::to_string(::getpid()) + ".yaml");
  std::ifstream in(kSealed);
  std::ofstream out(file);
  out << in.rdbuf() << "resolution: " << resolution << "\n";
  out.close();
  world::Problem p = world::load_problem(file);
  fs::remove(file);
  return p;
}

class StopMechanism : public ::testing::TestWithParam<std::string> {};

TEST_P(StopMechanism, NoticesTheLimitSoonAndStopsSoonAfterOnAWorkClock) {
  const std::string planner = GetParam();
  const std::uint64_t limit_calls = static_cast<std::uint64_t>(kTimeLimit / kSecondsPerCall);
  // The default resolution (many short iterations) and 1e-7 of the extent (edges of up to 10^7
  // CD calls: only polling inside the edge can stop them).
  for (const std::string resolution : {"", "1e-7"}) {
    SCOPED_TRACE(planner + " on sealed.yaml, resolution " + (resolution.empty() ? "default" : resolution));
    const world::Problem p = sealed_at(resolution);
    const Outcome a = run_on_work_clock(p, planner, 11);
    ASSERT_EQ(a.status, core::PlanStatus::kTimeout);
    ASSERT_GE(a.noticed_at, limit_calls);
    EXPECT_LE(a.noticed_at - limit_calls, kNoticeCalls) << "calls past the limit before a poll saw it";
    EXPECT_LE(a.work - a.noticed_at, kAfterCalls) << "calls after the limit was seen";
    // The clock is the work: the same seed stops at the same point, however busy the machine.
    const Outcome b = run_on_work_clock(p, planner, 11);
    EXPECT_EQ(a.work, b.work);
    EXPECT_EQ(a.nodes, b.nodes);
  }
}

INSTANTIATE_TEST_SUITE_P(Planners, StopMechanism, ::testing::ValuesIn(test::any_world_planners()),
                         [](const auto& info) {
                           std::string name = info.param;
                           for (char& ch : name) ch = (ch == '-') ? '_' : ch;
                           return name;
                         });

}  // namespace
}  // namespace amp::roadmap
