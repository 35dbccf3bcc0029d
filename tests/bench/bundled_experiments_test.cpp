// Every experiment file bundled in problems/experiments (and its subfolders) loads: its problems, planners, parameters,
// draws and the problems' own planner parameters are all checked before a run would start.
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "amp/bench/experiment.hpp"
#include "support/source_tree.hpp"

namespace amp::bench {
namespace {

TEST(BundledExperiments, EveryFileLoads) {
  const std::filesystem::path dir = std::filesystem::path(AMP_SOURCE_DIR) / "problems" / "experiments";
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
    if (e.path().extension() == ".yaml") files.push_back(e.path());
  }
  ASSERT_GE(files.size(), 8u);
  for (const auto& f : files) {
    SCOPED_TRACE(f.filename().string());
    Experiment e;
    ASSERT_NO_THROW(e = load_experiment(f));
    EXPECT_FALSE(e.problems.empty());
    EXPECT_FALSE(e.planners.empty());
    EXPECT_GT(e.runs, 0);
  }
}

TEST(BundledExperiments, RunCostVarianceIsThePapersTable1) {
  const Experiment e = load_experiment(std::filesystem::path(AMP_SOURCE_DIR) / "problems" / "experiments" /
                                       "run-cost-variance.yaml");
  EXPECT_EQ(e.runs, 240);
  ASSERT_EQ(e.problems.size(), 2u);
  EXPECT_EQ(e.problems[1].problem->defaults.params.at("steps"), "512");  // the 6-DOF puzzle's grid
  ASSERT_EQ(e.planners.size(), 3u);
  for (const auto& p : e.planners) EXPECT_EQ(p.draws.size(), 1u) << p.label;  // the metaplanner's draw
}

}  // namespace
}  // namespace amp::bench
