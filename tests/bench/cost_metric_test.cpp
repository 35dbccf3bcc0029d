// cost_metric.cpp: which names an experiment's `cost:` may take, and each run's value of it.
#include "amp/bench/cost_metric.hpp"

#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"

namespace amp::bench {
namespace {

using Kind = MetricSample::Kind;

core::RunRecord record() {
  core::RunRecord r;
  r.status = core::PlanStatus::kSolved;
  r.cd_calls_training = 5;
  r.cd_calls_planning = 30;
  r.cd_calls_query = 7;
  r.nodes = 12;
  r.wall_time_s = 0.25;
  r.path_length = 3.5;
  r.extra = {{"replans", 4.0}, {"path_ratio_median", std::numeric_limits<double>::quiet_NaN()}};
  return r;
}

TEST(CostMetric, ColumnsAreReadFromTheRecord) {
  const core::RunRecord r = record();
  EXPECT_EQ(metric_sample(r, "cd_calls").value, 42.0);  // training + planning + query, as runs.csv's column
  EXPECT_EQ(metric_sample(r, "cd_calls_training").value, 5.0);
  EXPECT_EQ(metric_sample(r, "nodes").value, 12.0);
  EXPECT_EQ(metric_sample(r, "wall_time_s").value, 0.25);
  EXPECT_EQ(metric_sample(r, "path_length").value, 3.5);
  EXPECT_EQ(metric_sample(r, "nodes").kind, Kind::kValue);
}

TEST(CostMetric, OtherNamesAreExtrasAndMayBeMissing) {
  const core::RunRecord r = record();
  EXPECT_EQ(metric_sample(r, "replans").kind, Kind::kValue);
  EXPECT_EQ(metric_sample(r, "replans").value, 4.0);
  EXPECT_EQ(metric_sample(r, "coverage").kind, Kind::kMissing);
  EXPECT_EQ(metric_sample(r, "path_ratio_median").kind, Kind::kMissing) << "NaN is no value";
}

TEST(CostMetric, PathMetricsTakeSolvedRunsOnly) {
  core::RunRecord r = record();
  r.status = core::PlanStatus::kTimeout;
  EXPECT_EQ(metric_sample(r, "path_length").kind, Kind::kExcluded);
  EXPECT_EQ(metric_sample(r, "path_clearance").kind, Kind::kExcluded);
  EXPECT_EQ(metric_sample(r, "cd_calls").kind, Kind::kValue) << "censored at the limit, not left out";
  EXPECT_TRUE(solved_only_metric("path_length"));
  EXPECT_FALSE(solved_only_metric("replans"));
}

TEST(CostMetric, RefusesTextColumnsAndNamesThatAreNoMetric) {
  for (const std::string ok : {"cd_calls", "wall_time_s", "path_length", "replans", "queries_solved", "a.b", "_x"}) {
    EXPECT_NO_THROW(check_cost_metric(ok)) << ok;
  }
  for (const std::string bad : {"status", "seed", "planner", "message", "param.k", "", "1x", "a b", "x;y", "x=1"}) {
    EXPECT_THROW(check_cost_metric(bad), ParameterError) << bad;
  }
  EXPECT_EQ(metric_label("cd_calls"), "CD calls");
  EXPECT_EQ(metric_label("replans"), "replans");
}

}  // namespace
}  // namespace amp::bench
