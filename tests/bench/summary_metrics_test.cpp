// summary.cpp: the tests use the experiment's cost, every extra metric gets descriptive statistics,
// and a cost that some runs lack skips the tests with a message instead of failing. The records are
// made by hand, so every expected number is computed here from the values written below.
#include "amp/bench/summary.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace amp::bench {
namespace {

Experiment two_methods(const std::string& cost) {
  Experiment e;
  e.name = "hand-made";
  e.runs = 4;
  e.cost = cost;
  e.problems.push_back({"P", "p.yaml", nullptr, {}});
  e.planners.push_back({"a", "prm", {}, {}, MethodKind::kPlanner});
  e.planners.push_back({"b", "pgcs", {}, {}, MethodKind::kNavigator});
  return e;
}

// Run i of method m: replans and coverage as extras, cd_calls and path_length in the record.
Trial trial(std::size_t m, int i, double replans, double path_length, bool solved = true) {
  Trial t;
  t.id = {m * 4 + static_cast<std::size_t>(i), 0, m, i};
  t.record.status = solved ? core::PlanStatus::kSolved : core::PlanStatus::kTimeout;
  t.record.cd_calls_planning = 100 + static_cast<std::uint64_t>(i);
  t.record.path_length = path_length;
  t.record.extra["replans"] = replans;
  t.record.extra["coverage"] = 0.5 + 0.1 * i;
  return t;
}

ExperimentMetrics metrics_of(const Experiment& e, const std::vector<Trial>& trials) {
  ExperimentMetrics m = empty_metrics(e);
  for (const Trial& t : trials) m[t.id.problem][t.id.planner].add(t);
  return m;
}

std::vector<Trial> trials() {
  return {trial(0, 0, 1, 10), trial(0, 1, 2, 12), trial(0, 2, 3, 14), trial(0, 3, 6, 16, false),
          trial(1, 0, 10, 20), trial(1, 1, 11, 22), trial(1, 2, 15, 21), trial(1, 3, 12, 23)};
}

TEST(SummaryMetrics, TestsAndCostStatisticsUseTheNamedExtra) {
  const Experiment e = two_methods("replans");
  const nlohmann::json s = summarize(e, metrics_of(e, trials()));
  const auto& p = s["problems"][0];
  EXPECT_EQ(s["experiment"]["cost"], "replans");
  EXPECT_EQ(p["tests"]["metric"], "replans");
  const auto& a = p["planners"][0]["cost"];
  EXPECT_EQ(a["metric"], "replans");
  EXPECT_EQ(a["n"], 4) << "a run stopped at a limit enters with what it had spent";
  EXPECT_EQ(a["missing"], 0);
  EXPECT_DOUBLE_EQ(a["mean"].get<double>(), (1 + 2 + 3 + 6) / 4.0);
  EXPECT_DOUBLE_EQ(a["median"].get<double>(), 2.5);
  EXPECT_DOUBLE_EQ(a["min"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(a["max"].get<double>(), 6.0);
  // Sample standard deviation of {1, 2, 3, 6}: mean 3, squares 4 + 1 + 0 + 9 = 14 over n - 1 = 3.
  EXPECT_NEAR(a["std"].get<double>(), std::sqrt(14.0 / 3.0), 1e-12);
  const auto& b = p["planners"][1]["cost"];
  EXPECT_DOUBLE_EQ(b["mean"].get<double>(), 12.0);
  // Every run of b replans more than every run of a: the groups differ, Kruskal-Wallis says so.
  EXPECT_LT(p["tests"]["kruskal_wallis"]["p_value"].get<double>(), 0.05);
  // CD calls are the same in both groups, so a test on them could not tell them apart this way.
  EXPECT_DOUBLE_EQ(p["planners"][0]["cd_calls"]["mean"].get<double>(), 101.5);
}

TEST(SummaryMetrics, PathLengthCostTakesSolvedRunsOnly) {
  const Experiment e = two_methods("path_length");
  const nlohmann::json s = summarize(e, metrics_of(e, trials()));
  const auto& a = s["problems"][0]["planners"][0]["cost"];
  EXPECT_EQ(a["n"], 3);
  EXPECT_EQ(a["solved_only"], true);
  EXPECT_DOUBLE_EQ(a["mean"].get<double>(), 12.0);
  EXPECT_EQ(s["problems"][0]["tests"]["metric"], "path_length");
}

TEST(SummaryMetrics, EveryExtraGetsDescriptiveStatistics) {
  const Experiment e = two_methods("cd_calls");
  const nlohmann::json s = summarize(e, metrics_of(e, trials()));
  const auto& a = s["problems"][0]["planners"][0];
  ASSERT_TRUE(a.contains("metrics"));
  EXPECT_NEAR(a["metrics"]["coverage"]["mean"].get<double>(), 0.65, 1e-12);
  EXPECT_DOUBLE_EQ(a["metrics"]["replans"]["max"].get<double>(), 6.0);
  EXPECT_TRUE(a["metrics"]["replans"].contains("histogram"));
  // The default cost leaves the summary as it was: no "cost" entry, tests on CD calls.
  EXPECT_FALSE(a.contains("cost"));
  EXPECT_FALSE(s["experiment"].contains("cost"));
  EXPECT_EQ(s["problems"][0]["tests"]["metric"], "cd_calls");
}

TEST(SummaryMetrics, ACostSomeRunsLackSkipsTheTestsSayingWhere) {
  const Experiment e = two_methods("replans");
  std::vector<Trial> t = trials();
  t[5].record.extra.erase("replans");
  t[6].record.extra["replans"] = std::numeric_limits<double>::quiet_NaN();
  const nlohmann::json s = summarize(e, metrics_of(e, t));
  const auto& tests = s["problems"][0]["tests"];
  ASSERT_TRUE(tests.contains("skipped"));
  EXPECT_EQ(tests["skipped"], "metric 'replans' missing in runs (2 of 'b')");
  EXPECT_EQ(s["problems"][0]["planners"][1]["cost"]["missing"], 2);
  EXPECT_EQ(s["problems"][0]["planners"][1]["cost"]["n"], 2);
  EXPECT_EQ(s["problems"][0]["planners"][1]["metrics"]["replans"]["n"], 2);
}

TEST(SummaryMetrics, AnExtraNoRunHasIsReportedNotThrown) {
  const Experiment e = two_methods("no_such_metric");
  nlohmann::json s;
  ASSERT_NO_THROW(s = summarize(e, metrics_of(e, trials())));
  EXPECT_EQ(s["problems"][0]["tests"]["skipped"], "metric 'no_such_metric' missing in runs (4 of 'a', 4 of 'b')");
  EXPECT_EQ(s["problems"][0]["planners"][0]["cost"]["n"], 0);
}

}  // namespace
}  // namespace amp::bench
