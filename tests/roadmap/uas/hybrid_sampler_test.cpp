// uas/hybrid_sampler.cpp: one Hybrid PRM sampler set, a bandit over samplers rewarded by each
// sample's structural effect per CD call.
#include "amp/roadmap/uas/hybrid_sampler.hpp"

#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "roadmap/test_worlds.hpp"

namespace amp::roadmap {
namespace {

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

// A failed sample updates its arm at once with reward 0, which leaves every weight as it was; it
// counts as chosen but not as a sample, and no reward is pending afterwards.
TEST(HybridSampler, FailedSamplesAreChosenButNeitherCountedNorRewarded) {
  const world::Problem p = test::point_problem(true);
  core::Counters counters;
  const auto checker = p.environment->make_checker(counters);
  std::vector<HybridSampler::Arm> arms;
  arms.push_back({"fails", std::make_unique<CostlySampler>(*checker, 3, false)});
  arms.push_back({"works", std::make_unique<CostlySampler>(*checker, 1, true)});
  HybridSampler h(std::move(arms), *checker);
  core::Rng rng(2);
  State q;
  int failures = 0;
  for (int i = 0; i < 40; ++i) {
    const std::vector<double> before = h.bandit().log_weights();
    if (!h.sample(rng, q)) {
      ++failures;
      EXPECT_EQ(h.bandit().log_weights(), before) << "sample " << i;
      h.reward_last(Insertion{7, false, 3, 0, 0});  // nothing pending: ignored
      EXPECT_EQ(h.bandit().log_weights(), before) << "sample " << i;
    } else {
      h.reward_last(Insertion{7, false, 3, 0, 0});  // cc-create: reward 1 for the working arm
      EXPECT_GT(h.bandit().log_weights()[1] - h.bandit().log_weights()[0], before[1] - before[0]);
    }
  }
  EXPECT_GT(h.bandit().probabilities()[1], 0.5);
  EXPECT_EQ(h.chosen(0) + h.chosen(1), 40u);
  EXPECT_EQ(h.chosen(0), static_cast<std::uint64_t>(failures));
  EXPECT_EQ(h.samples(0), 0u);
  EXPECT_EQ(h.samples(1), h.chosen(1));
  EXPECT_GT(failures, 5);
  EXPECT_EQ(h.arm_name(0), "fails");
  std::map<std::string, double> extra;
  h.report(extra);
  EXPECT_EQ(extra.at("chosen_fails"), static_cast<double>(failures));
  EXPECT_EQ(extra.at("samples_fails"), 0.0);
  EXPECT_THROW(HybridSampler({}, *checker), ParameterError);
}

}  // namespace
}  // namespace amp::roadmap
