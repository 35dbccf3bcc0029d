// A run ends within its time limit plus 5 % + 50 ms of wall time, measured around execute_run
// (planner, query, smoothing and the path clearance included) and execute_navigation. A
// limit-honouring test, not a performance test: the goal is sealed, so every run lasts exactly as
// long as its limit lets it. Wall time depends on the machine's load, so this file is the `timing`
// label, outside the default suite: CI runs it alone after the suite (.ci/run, `make timing`). The
// default suite tests the mechanism deterministically (stop_mechanism_test.cpp).
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

#include <unistd.h>

#include <gtest/gtest.h>

#include "amp/nav/navigator_catalog.hpp"
#include "amp/roadmap/run.hpp"
#include "amp/world/problem.hpp"
#include "support/time_allowance.hpp"
#include "support/source_tree.hpp"

namespace amp::roadmap {
namespace {

namespace fs = std::filesystem;

constexpr double kTimeLimit = 1.0;
constexpr double kAllowance = test::time_allowance(kTimeLimit);
constexpr std::size_t kNoNodeLimit = 1000000000;

const fs::path kSealed = fs::path(AMP_SOURCE_DIR) / "tests" / "apps" / "data" / "sealed.yaml";

double timed_run(const world::Problem& p, const std::string& planner, core::RunRecord& record) {
  const auto t0 = std::chrono::steady_clock::now();
  record = execute_run(p, planner, {}, 11, kTimeLimit, kNoNodeLimit).record;
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The sealed goal at the default resolution (many short iterations) and at 1e-7 of the extent
// (edges of up to 10^7 CD calls, seconds each without polling inside the edge).
class RunLimits : public ::testing::TestWithParam<const char*> {
 protected:
  static world::Problem fine_sealed() {
    const fs::path file = fs::temp_directory_path() / ("amp_run_limits_" + std::to_string(::getpid()) + ".yaml");
    std::ifstream in(kSealed);
    std::ofstream out(file);
    out << in.rdbuf() << "resolution: 1e-7\n";
    out.close();
    world::Problem p = world::load_problem(file);
    fs::remove(file);
    return p;
  }
};

TEST_P(RunLimits, OneSecondLimitEndsWithinTheAllowance) {
  const std::string planner = GetParam();
  const std::pair<world::Problem, const char*> cases[] = {{world::load_problem(kSealed), "the default resolution"},
                                                           {fine_sealed(), "resolution 1e-7"}};
  for (const auto& [p, label] : cases) {
    SCOPED_TRACE(planner + " on sealed.yaml at " + label);
    core::RunRecord r;
    const double wall = timed_run(p, planner, r);
    EXPECT_EQ(r.status, core::PlanStatus::kTimeout) << r.message;
    EXPECT_LE(wall, kTimeLimit + kAllowance);
    EXPECT_LE(r.wall_time_s, wall);
  }
}

INSTANTIATE_TEST_SUITE_P(Planners, RunLimits, ::testing::Values("prm", "prm-c", "uas", "rrt-connect"));

// Navigation methods told to work for hours (PGCS's exploration steps, a goal tolerance hardly
// ever met) end on the same promise.
TEST(NavigationLimits, OneSecondLimitEndsWithinTheAllowance) {
  const world::Problem office = world::load_problem(fs::path(AMP_SOURCE_DIR) / "problems" / "office-map.yaml");
  const std::pair<const char*, core::ParamMap> cases[] = {
      {"pgcs", {{"steps", 1e7}}},
      {"policy-search", {{"max_time", 1e5}, {"goal_tolerance", 1e-5}}},
      {"dwa", {{"max_time", 1e5}, {"goal_tolerance", 1e-5}}}};
  for (const auto& [method, params] : cases) {
    SCOPED_TRACE(method);
    const auto t0 = std::chrono::steady_clock::now();
    const nav::NavigationOutcome out = nav::execute_navigation(office, method, params, 11, kTimeLimit);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_NE(out.record.status, core::PlanStatus::kError) << out.record.message;
    EXPECT_LE(wall, kTimeLimit + kAllowance);
  }
}

}  // namespace
}  // namespace amp::roadmap
