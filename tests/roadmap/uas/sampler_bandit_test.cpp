// uas/sampler_bandit.cpp: Hybrid PRM's EXP3-style selection of a sampler.
#include "amp/roadmap/uas/sampler_bandit.hpp"

#include <cmath>
#include <numeric>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"

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

// gamma = 1 is pure chance: the probabilities stay uniform whatever the rewards; a reward of 0
// changes no weight (EXP3 updates by the reward only).
TEST(SamplerBandit, GammaOneStaysUniformAndZeroRewardChangesNothing) {
  SamplerBandit chance(3, 1.0);
  chance.update(1, 1.0, 0.01);
  for (double p : chance.probabilities()) EXPECT_DOUBLE_EQ(p, 1.0 / 3.0);
  SamplerBandit b(2, 0.2);
  b.update(0, 1.0, 1.0);  // rhat = 1 / (0.5 * 1) = 2: log w0 = 0.2 * 2 / 2 = 0.2
  const std::vector<double> before = b.probabilities();
  EXPECT_NEAR(b.log_weights()[1] - b.log_weights()[0], -0.2, 1e-15);
  EXPECT_NEAR(before[0], 0.8 * std::exp(0.2) / (std::exp(0.2) + 1.0) + 0.1, 1e-15);
  b.update(1, 0.0, 3.0);
  EXPECT_EQ(b.probabilities(), before);
  EXPECT_THROW(b.update(0, -1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(b.update(0, 1.0, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace amp::roadmap
