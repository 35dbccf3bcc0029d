// runs_csv.cpp: a navigation method's metrics (extras) read back from runs.csv exactly as written,
// whatever their value, so resume, merge and the derived outputs see the numbers the run reported.
#include "amp/bench/runs_csv.hpp"

#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <string>

#include <gtest/gtest.h>

namespace amp::bench {
namespace {

namespace fs = std::filesystem;

TEST(RunsCsvExtras, ReadBackBitForBit) {
  Experiment e;
  e.name = "extras";
  e.runs = 2;
  e.problems.push_back({"Office", "office.yaml", nullptr, {}});
  e.planners.push_back({"pgcs-small", "pgcs", {}, {}, MethodKind::kNavigator});
  const std::map<std::string, double> extras = {{"replans", 17.0},
                                                {"replans_median", 2.5},
                                                {"solved_fraction", 2.0 / 3.0},
                                                {"quantisation_error", 1e-300},
                                                {"explore_time_s", 0.1 + 0.2},
                                                {"path_ratio_median", std::numeric_limits<double>::quiet_NaN()},
                                                {"query_time_median_s", std::numeric_limits<double>::infinity()},
                                                {"clusters", -0.0}};
  const fs::path file = fs::temp_directory_path() / ("amp-runs-csv-extras-" + std::to_string(::getpid()) + ".csv");
  {
    RunsCsvWriter w(file, e, false);
    for (int run = 0; run < 2; ++run) {
      Trial t;
      t.id = trial_id(e, static_cast<std::size_t>(run));
      t.seed = 42 + static_cast<std::uint64_t>(run);
      t.record.status = run == 0 ? core::PlanStatus::kSolved : core::PlanStatus::kTimeout;
      t.record.path_length = 12.75;
      t.record.extra = extras;
      w.add(t);
    }
    w.finish();
  }
  int rows = 0;
  for_each_trial(file, e, [&](const Trial& t) {
    ++rows;
    ASSERT_EQ(t.record.extra.size(), extras.size());
    for (const auto& [name, value] : extras) {
      const double got = t.record.extra.at(name);
      if (std::isnan(value)) {
        EXPECT_TRUE(std::isnan(got)) << name;
      } else {
        EXPECT_EQ(got, value) << name;
        EXPECT_EQ(std::signbit(got), std::signbit(value)) << name;
      }
    }
    EXPECT_EQ(t.record.path_length, 12.75);
  });
  EXPECT_EQ(rows, 2);
  fs::remove(file);
}

}  // namespace
}  // namespace amp::bench
