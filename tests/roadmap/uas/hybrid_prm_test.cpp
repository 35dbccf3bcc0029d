#include "amp/roadmap/uas/hybrid_prm.hpp"

#include "amp/core/error.hpp"

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/path_checks.hpp"

#include "amp/roadmap/catalog/planner_registry.hpp"
#include "amp/roadmap/run.hpp"
#include "amp/world/problem.hpp"
#include "roadmap/test_worlds.hpp"
#include "support/source_tree.hpp"

namespace amp::roadmap {
namespace {

// --- The planners on bundled problems -------------------------------------------------------------

constexpr double kNoTimeLimit = 1e6;
constexpr std::size_t kNodeLimit = 20000;

const world::Problem& bundled(const std::string& name) {
  static const world::Problem walls = world::load_problem(std::string(AMP_SOURCE_DIR) + "/problems/walls.yaml");
  static const world::Problem maze = world::load_problem(std::string(AMP_SOURCE_DIR) + "/problems/maze.yaml");
  return name == "walls" ? walls : maze;
}


class SamplerPlanners : public ::testing::TestWithParam<std::tuple<std::string, std::string>> {};

TEST_P(SamplerPlanners, SolveWithValidPathsAndRepeatBitForBit) {
  const auto& [planner, problem] = GetParam();
  const world::Problem& p = bundled(problem);
  const RunOutcome a = execute_run(p, planner, {}, 21, kNoTimeLimit, kNodeLimit);
  ASSERT_EQ(a.record.status, core::PlanStatus::kSolved) << planner << " on " << problem;
  amp::test::expect_valid_path(p, a.path);
  const RunOutcome b = execute_run(p, planner, {}, 21, kNoTimeLimit, kNodeLimit);
  EXPECT_EQ(a.path, b.path);
  EXPECT_EQ(a.record.cd_calls(), b.record.cd_calls());
  EXPECT_GT(a.record.extra.at("cc_create") + a.record.extra.at("cc_merge"), 0.0);
}

INSTANTIATE_TEST_SUITE_P(Bundled, SamplerPlanners,
                         ::testing::Combine(::testing::Values("hybrid-prm", "gaussian-prm", "obprm", "bridge-prm"),
                                            ::testing::Values("walls", "maze")),
                         [](const auto& info) {
                           std::string n = std::get<0>(info.param) + "_" + std::get<1>(info.param);
                           for (char& c : n) c = c == '-' ? '_' : c;
                           return n;
                         });

TEST(HybridPrm, HaltonSequenceSolvesWithValidPathsRepeatsAndDiffersFromRandom) {
  for (const char* problem : {"walls", "maze"}) {
    const world::Problem& p = bundled(problem);
    const core::ParamMap halton{{"sequence", "halton"}};
    const RunOutcome a = execute_run(p, "hybrid-prm", halton, 21, kNoTimeLimit, kNodeLimit);
    ASSERT_EQ(a.record.status, core::PlanStatus::kSolved) << problem;
    amp::test::expect_valid_path(p, a.path);
    const RunOutcome b = execute_run(p, "hybrid-prm", halton, 21, kNoTimeLimit, kNodeLimit);
    EXPECT_EQ(a.path, b.path);
    EXPECT_EQ(a.record.cd_calls(), b.record.cd_calls());
    const RunOutcome r = execute_run(p, "hybrid-prm", {{"sequence", "random"}}, 21, kNoTimeLimit, kNodeLimit);
    EXPECT_NE(a.record.cd_calls(), r.record.cd_calls()) << "the sequence option changed nothing on " << problem;
  }
  EXPECT_THROW(execute_run(bundled("walls"), "hybrid-prm", {{"sequence", "sobol"}}, 1, kNoTimeLimit, kNodeLimit),
               ParameterError);
}

TEST(HybridPrm, ReportsProbabilitiesSamplesAndClasses) {
  const world::Problem& p = bundled("walls");
  const RunOutcome o = execute_run(p, "hybrid-prm", {{"bridge", true}}, 4, kNoTimeLimit, kNodeLimit);
  ASSERT_EQ(o.record.status, core::PlanStatus::kSolved);
  double prob = 0.0, samples = 0.0;
  for (const char* s : {"uniform", "gaussian_r", "gaussian_2r", "obprm", "bridge"}) {
    const double q = o.record.extra.at(std::string("prob_") + s);
    EXPECT_GE(q, 0.5 / 5 - 1e-12) << s;
    prob += q;
    samples += o.record.extra.at(std::string("samples_") + s);
  }
  EXPECT_NEAR(prob, 1.0, 1e-12);
  const double classes = o.record.extra.at("cc_create") + o.record.extra.at("cc_merge") +
                         o.record.extra.at("cc_expand") + o.record.extra.at("cc_oversample");
  EXPECT_EQ(samples, classes);                                  // every sample was inserted and classified
  EXPECT_EQ(classes + 2.0, static_cast<double>(o.record.nodes));  // + start and goal
  EXPECT_EQ(o.record.extra.at("sampler_distance_fallback"), 0.0);
}

}  // namespace
}  // namespace amp::roadmap
