#include "amp/roadmap/uas/hybrid_prm.hpp"

#include "amp/core/error.hpp"

#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/path_checks.hpp"

#include "amp/roadmap/catalog/planner_registry.hpp"
#include "amp/roadmap/run.hpp"
#include "amp/roadmap/uas/sampler_bandit.hpp"
#include "amp/world/problem.hpp"
#include "roadmap/test_worlds.hpp"

namespace amp::roadmap {
namespace {

TEST(SamplerBandit, StartsUniformAndFollowsAHandComputedStep) {
  SamplerBandit b(4, 0.5);
  for (double p : b.probabilities()) EXPECT_DOUBLE_EQ(p, 0.25);
  // Arm 2, reward 1, cost 1: rhat = 1 / (0.25 * 1) = 4, w2 = exp(0.5 * 4 / 4) = e^0.5, the others 1.
  b.update(2, 1.0, 1.0);
  const double w = std::exp(0.5), sum = w + 3.0;
  EXPECT_NEAR(b.probabilities()[2], 0.5 * w / sum + 0.125, 1e-15);
  EXPECT_NEAR(b.probabilities()[0], 0.5 * 1 / sum + 0.125, 1e-15);
  // Arm 0 next, reward 0.25, cost 2, with its new Pr p0: rhat = 0.25 / (p0 * 2); log w0 += 0.5 * rhat / 4.
  const double p0 = b.probabilities()[0];
  b.update(0, 0.25, 2.0);
  const double w0 = std::exp(0.5 * (0.25 / (p0 * 2.0)) / 4.0), sum2 = w0 + w + 2.0;
  EXPECT_NEAR(b.probabilities()[0], 0.5 * w0 / sum2 + 0.125, 1e-15);
  EXPECT_NEAR(b.probabilities()[2], 0.5 * w / sum2 + 0.125, 1e-15);
  EXPECT_NEAR(b.probabilities()[3], 0.5 / sum2 + 0.125, 1e-15);
}

TEST(SamplerBandit, ProbabilitiesSumToOneAndKeepTheirFloorUnderExtremeRewards) {
  SamplerBandit b(5, 0.5);
  core::Rng rng(3);
  for (int i = 0; i < 20000; ++i) {
    const std::size_t s = b.choose(rng);
    // Costs down to 1e-3 make rhat as large as 1 / (0.1 * 1e-3): weights that would overflow a double.
    b.update(s, s == 1 ? 1.0 : rng.uniform01(), s == 1 ? 1e-3 : 1.0);
    const auto& p = b.probabilities();
    ASSERT_NEAR(std::accumulate(p.begin(), p.end(), 0.0), 1.0, 1e-12);
    for (double q : p) ASSERT_GE(q, 0.5 / 5 - 1e-15);
  }
  EXPECT_NEAR(b.probabilities()[1], 0.5 + 0.1, 1e-9);  // the cheap arm took all of the learned share
  EXPECT_THROW(SamplerBandit(0, 0.5), ParameterError);
  EXPECT_THROW(SamplerBandit(2, 0.0), ParameterError);
  EXPECT_THROW(b.update(9, 1.0, 1.0), std::invalid_argument);
}

TEST(SamplerBandit, ChoosesByItsProbabilities) {
  SamplerBandit b(3, 0.5);
  b.update(0, 1.0, 0.5);  // arm 0 well ahead
  core::Rng rng(5);
  std::vector<int> hits(3, 0);
  constexpr int kDraws = 30000;
  for (int i = 0; i < kDraws; ++i) ++hits[b.choose(rng)];
  for (int s = 0; s < 3; ++s) EXPECT_NEAR(hits[s] / static_cast<double>(kDraws), b.probabilities()[s], 0.01);
}

// Spends a fixed number of CD calls per sample and succeeds or not.
class CostlySampler final : public Sampler {
 public:
  CostlySampler(const world::ValidityChecker& c, int cost, bool ok) : checker_(&c), cost_(cost), ok_(ok) {}
  bool sample(core::Rng&, State& out) override {
    out = test::state2(1, 1);
    for (int i = 0; i < cost_; ++i) checker_->is_valid(out);
    return ok_;
  }

 private:
  const world::ValidityChecker* checker_;
  int cost_;
  bool ok_;
};

TEST(HybridSampler, CostIsNormalisedByTheRunningMeanAndRewardFollowsTheNodeClass) {
  const world::Problem p = test::point_problem(true);
  core::Counters counters;
  const auto checker = p.environment->make_checker(counters);
  std::vector<HybridSampler::Arm> arms;
  arms.push_back({"cheap", std::make_unique<CostlySampler>(*checker, 2, true)});
  arms.push_back({"dear", std::make_unique<CostlySampler>(*checker, 6, true)});
  HybridSampler h(std::move(arms), *checker, {0.5, 4.0});
  core::Rng rng(1);
  State q;
  ASSERT_TRUE(h.sample(rng, q));
  const std::size_t first = h.samples(0) == 1 ? 0 : 1;
  // The first sample's cost is the mean itself: normalised cost 1; cc-create reward 1; Pr = 1/2.
  h.reward_last(Insertion{7, false, 3, 0, 0});
  EXPECT_NEAR(h.bandit().log_weights()[first], 0.0, 1e-15);
  EXPECT_NEAR(h.bandit().log_weights()[1 - first], -0.5 * (1.0 / 0.5) / 2.0, 1e-15);
  // A second reward without a new sample is ignored.
  h.reward_last(Insertion{8, false, 3, 0, 0});
  EXPECT_NEAR(h.bandit().log_weights()[1 - first], -0.5, 1e-15);
  // Rewards: cc-merge 1, cc-expand with visibility 0.5 (1 of 2) exp(-4 * 0.25), oversample 1.0 -> e^-4.
  EXPECT_DOUBLE_EQ(h.reward(Insertion{0, false, 4, 4, 2}), 1.0);
  EXPECT_DOUBLE_EQ(h.reward(Insertion{0, false, 3, 1, 1}), std::exp(-4.0 / 9.0));
  EXPECT_DOUBLE_EQ(h.reward(Insertion{0, false, 2, 2, 1}), std::exp(-4.0));
  // Running mean: costs 2 (or 6) then 6 -> the next normalised cost of 4 CD calls is 4 / mean(c1, 6, 4).
  const double c1 = first == 0 ? 2.0 : 6.0;
  h.normalised_cost(6);
  EXPECT_DOUBLE_EQ(h.normalised_cost(4), 4.0 / ((c1 + 6.0 + 4.0) / 3.0));
  std::map<std::string, double> extra;
  h.report(extra);
  EXPECT_EQ(extra.at(first == 0 ? "samples_cheap" : "samples_dear"), 1.0);
  EXPECT_NEAR(extra.at("prob_cheap") + extra.at("prob_dear"), 1.0, 1e-15);
}

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
    const ParamMap halton{{"sequence", "halton"}};
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
