#include "amp/roadmap/uas/uas.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "support/path_checks.hpp"

#include "amp/core/error.hpp"
#include "amp/roadmap/catalog/planner_registry.hpp"
#include "amp/roadmap/run.hpp"
#include "amp/world/problem.hpp"
#include "roadmap/test_worlds.hpp"
#include "support/bundled_problems.hpp"

namespace amp::roadmap {
namespace {

constexpr double kNoTimeLimit = 1e6;

const world::Problem& bundled(const std::string& name) { return amp::test::bundled_problem(name + ".yaml"); }

// --- The planner ------------------------------------------------------------------------------------

class UasPlanner : public ::testing::TestWithParam<std::tuple<std::string, std::string>> {};

TEST_P(UasPlanner, SolvesWithValidPathsTrainingCostAndRepeatsBitForBit) {
  const auto& [clustering, problem] = GetParam();
  const world::Problem& p = bundled(problem);
  const core::ParamMap params{{"clustering", clustering}};
  const RunOutcome a = execute_run(p, "uas", params, 11, kNoTimeLimit, 20000);
  ASSERT_EQ(a.record.status, core::PlanStatus::kSolved) << clustering << " on " << problem;
  amp::test::expect_valid_path(p, a.path);
  const auto& x = a.record.extra;
  EXPECT_EQ(x.at("training_nodes"), 200.0);
  EXPECT_GT(a.record.cd_calls_training, 0u);
  EXPECT_GT(a.record.cd_calls_planning, 0u);
  EXPECT_GE(x.at("clusters"), 1.0);
  EXPECT_EQ(x.at("uas_fallback_global"), x.at("clusters") < 2 ? 1.0 : 0.0);
  // The training roadmap is reused: the roadmap holds it, the seeds and the planning samples.
  EXPECT_EQ(x.at("planning_nodes") + 200.0, static_cast<double>(a.record.nodes));
  const RunOutcome b = execute_run(p, "uas", params, 11, kNoTimeLimit, 20000);
  EXPECT_EQ(a.path, b.path);
  EXPECT_EQ(a.record.cd_calls(), b.record.cd_calls());
  EXPECT_EQ(a.record.extra, b.record.extra);
}

INSTANTIATE_TEST_SUITE_P(Bundled, UasPlanner,
                         ::testing::Combine(::testing::Values("kmeans", "ward", "pgmeans", "auto"),
                                            ::testing::Values("walls", "maze")),
                         [](const auto& info) { return std::get<0>(info.param) + "_" + std::get<1>(info.param); });

TEST(Uas, HaltonSequenceSolvesWithValidPathsAndRepeatsBitForBit) {
  for (const char* problem : {"walls", "maze"}) {
    const world::Problem& p = bundled(problem);
    const core::ParamMap params{{"clustering", "ward"}, {"sequence", "halton"}};
    const RunOutcome a = execute_run(p, "uas", params, 5, kNoTimeLimit, 20000);
    ASSERT_EQ(a.record.status, core::PlanStatus::kSolved) << problem;
    amp::test::expect_valid_path(p, a.path);
    const RunOutcome b = execute_run(p, "uas", params, 5, kNoTimeLimit, 20000);
    EXPECT_EQ(a.path, b.path);
    EXPECT_EQ(a.record.extra, b.record.extra);
    // Training does not use the sequence: the same regions as with random draws.
    const RunOutcome r = execute_run(p, "uas", {{"clustering", "ward"}}, 5, kNoTimeLimit, 20000);
    EXPECT_EQ(a.record.cd_calls_training, r.record.cd_calls_training);
    EXPECT_EQ(a.record.extra.at("clusters"), r.record.extra.at("clusters"));
  }
}

TEST(Uas, FallsBackToGlobalHybridPrmWhenClusteringFindsOneCluster) {
  // PG-means often accepts one Gaussian for the maze's training set; look for such a seed and check
  // that the run then sampled the whole space with one sampler set (global prob_ extras).
  const world::Problem& p = bundled("maze");
  int fallbacks = 0;
  for (std::uint64_t seed = 1; seed <= 6 && fallbacks == 0; ++seed) {
    const RunOutcome o = execute_run(p, "uas", {{"clustering", "pgmeans"}}, seed, kNoTimeLimit, 20000);
    ASSERT_EQ(o.record.status, core::PlanStatus::kSolved);
    if (o.record.extra.at("clusters") != 1.0) continue;
    ++fallbacks;
    EXPECT_EQ(o.record.extra.at("uas_fallback_global"), 1.0);
    EXPECT_TRUE(o.record.extra.contains("prob_obprm"));
    EXPECT_FALSE(o.record.extra.contains("region0_prob_obprm"));
    amp::test::expect_valid_path(p, o.path);
  }
  EXPECT_EQ(fallbacks, 1) << "no seed in 1..6 gave one cluster";
}

TEST(Uas, OnARegionRunEachRegionLearnsItsOwnSamplerProbabilities) {
  const RunOutcome o = execute_run(bundled("maze"), "uas", {{"clustering", "kmeans"}}, 2, kNoTimeLimit, 20000);
  ASSERT_EQ(o.record.status, core::PlanStatus::kSolved);
  const int c = static_cast<int>(o.record.extra.at("clusters"));
  ASSERT_GE(c, 2);
  for (int r = 0; r < c; ++r) {
    double sum = 0.0;
    for (const char* s : {"uniform", "gaussian_r", "gaussian_2r", "obprm"}) {
      const double q = o.record.extra.at("region" + std::to_string(r) + "_prob_" + s);
      EXPECT_GE(q, 0.5 / 4 - 1e-12);
      sum += q;
    }
    EXPECT_NEAR(sum, 1.0, 1e-12);
    EXPECT_GT(o.record.extra.at("region" + std::to_string(r) + "_rounds"), 0.0);
  }
  // The whole space is the last region, with the regions' mean weight; each region's rounds follow
  // its weight (1 + its training nodes of visibility < 1/2) to within one round.
  EXPECT_EQ(o.record.extra.at("regions"), c + 1.0);
  double mean = 0.0;
  for (int r = 0; r < c; ++r) mean += o.record.extra.at("region" + std::to_string(r) + "_weight") / c;
  EXPECT_DOUBLE_EQ(o.record.extra.at("region" + std::to_string(c) + "_weight"), mean);
  double rounds = 0.0, weights = 0.0;
  for (int r = 0; r <= c; ++r) {
    rounds += o.record.extra.at("region" + std::to_string(r) + "_rounds");
    weights += o.record.extra.at("region" + std::to_string(r) + "_weight");
  }
  for (int r = 0; r <= c; ++r) {
    const std::string i = std::to_string(r);
    EXPECT_NEAR(o.record.extra.at("region" + i + "_rounds"), rounds * o.record.extra.at("region" + i + "_weight") / weights,
                1.0);
  }
  const RunOutcome boxes_only = execute_run(bundled("maze"), "uas", {{"clustering", "kmeans"}, {"whole_space_region", false}},
                                            2, kNoTimeLimit, 20000);
  ASSERT_EQ(boxes_only.record.status, core::PlanStatus::kSolved);
  EXPECT_EQ(boxes_only.record.extra.at("regions"), boxes_only.record.extra.at("clusters"));
  EXPECT_FALSE(boxes_only.record.extra.contains(
      "region" + std::to_string(static_cast<int>(boxes_only.record.extra.at("clusters"))) + "_rounds"));
}

TEST(Uas, StopsAtTheNodeLimitDuringTrainingOrPlanning) {
  const world::Problem& p = bundled("maze");
  const RunOutcome early = execute_run(p, "uas", {}, 1, kNoTimeLimit, 50);  // inside the training
  EXPECT_EQ(early.record.status, core::PlanStatus::kNodeLimit);
  EXPECT_EQ(early.record.extra.at("training_nodes"), 50.0);
  const RunOutcome later = execute_run(p, "uas", {}, 1, kNoTimeLimit, 400);
  EXPECT_EQ(later.record.status, core::PlanStatus::kNodeLimit);
  EXPECT_EQ(later.record.nodes, 400u);
}

TEST(Uas, WithoutReuseThePlanningRoadmapStartsFromTheSeeds) {
  const RunOutcome o =
      execute_run(bundled("walls"), "uas", {{"reuse_training", false}}, 5, kNoTimeLimit, 20000);
  ASSERT_EQ(o.record.status, core::PlanStatus::kSolved);
  EXPECT_EQ(o.record.extra.at("planning_nodes"), static_cast<double>(o.record.nodes));
  amp::test::expect_valid_path(bundled("walls"), o.path);
}

}  // namespace
}  // namespace amp::roadmap
