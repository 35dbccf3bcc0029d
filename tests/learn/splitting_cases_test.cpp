#include "amp/learn/splitting_cases.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/core/rng.hpp"

namespace amp::learn {
namespace {

std::vector<const CaseUse*> pointers(const std::vector<CaseUse>& uses) {
  std::vector<const CaseUse*> p;
  for (const CaseUse& u : uses) p.push_back(&u);
  return p;
}

// A 2^4 factorial design (each output 0.4 or 0.6): the centred columns are orthogonal, so by hand
// the least-squares slopes are the generating ones, and a residual along the four-way interaction
// (orthogonal to every column) leaves them unchanged: RSS = 16 d^2 over 16 - 5 degrees of freedom,
// Var(slope) = s^2 / (16 x 0.1^2), t = slope / sqrt(s^2 / 0.16).
TEST(SplittingCases, TheFitOnAnOrthogonalDesignGivesTheSlopesAndTByHand) {
  const double slope[4] = {2.0, -1.0, 0.0, 0.5};
  const double d = 0.01;
  std::vector<CaseUse> uses;
  for (int i = 0; i < 16; ++i) {
    CaseUse u;
    double sign_product = 1.0;
    u.credit = 0.3;
    for (int o = 0; o < 4; ++o) {
      const double s = (i >> o) & 1 ? 1.0 : -1.0;
      sign_product *= s;
      u.outputs[o] = 0.5 + 0.1 * s;
      u.credit += slope[o] * u.outputs[o];
    }
    u.credit += d * sign_product;
    uses.push_back(u);
  }
  const auto p = pointers(uses);
  const OutputSlopes f = SplittingCaseLibrary::fit(p.data(), 16);
  const double se = std::sqrt(16 * d * d / 11 / 0.16);
  for (int o = 0; o < 4; ++o) {
    EXPECT_NEAR(f.slope[o], slope[o], 1e-12) << o;
    EXPECT_NEAR(f.t[o], slope[o] / se, 1e-6) << o;
  }
  EXPECT_EQ(f.uses, 16);
}

TEST(SplittingCases, AFitOfTooFewUsesOrOfAPinnedOutputGivesNoSlope) {
  std::vector<CaseUse> uses(12);
  for (std::size_t i = 0; i < uses.size(); ++i) {
    uses[i].outputs = {1.0, 0.1 * static_cast<double>(i % 3), 0.05 * static_cast<double>(i % 4), 0.5};
    uses[i].credit = uses[i].outputs[1] + 0.01 * static_cast<double>(i % 2);
  }
  const auto p = pointers(uses);
  const OutputSlopes few = SplittingCaseLibrary::fit(p.data(), 7);  // 2 slopes: 4 degrees of freedom
  for (int o = 0; o < 4; ++o) EXPECT_EQ(few.t[o], 0.0);
  const OutputSlopes all = SplittingCaseLibrary::fit(p.data(), 12);
  EXPECT_EQ(all.t[0], 0.0);  // pinned at 1
  EXPECT_EQ(all.t[3], 0.0);  // pinned at 0.5
  EXPECT_GT(all.t[1], 2.0);
}

// A choice's credit is the mean of the `horizon` rewards from its own interval on.
TEST(SplittingCases, ACreditIsTheMeanRewardOverTheHorizon) {
  SplittingCaseSettings s;
  s.horizon = 3;
  s.refit_every = 16;
  SplittingCaseLibrary lib(s, {0.5, 0.5, 0.5, 0.5});
  core::Rng rng(1);
  lib.begin_episode();
  const double rewards[] = {0.9, -0.3, 0.6, 0.0, 1.0};
  std::vector<CaseOutputs> chosen;
  for (const double r : rewards) {
    chosen.push_back(lib.choose({0.1, 0.2, 0.3, 0.4}, rng));
    lib.reward(r);
  }
  const SplittingCase& c = lib.at(0);
  ASSERT_EQ(c.uses.size(), 3u);  // the last two are still within their horizons
  EXPECT_NEAR(c.uses[0].credit, (0.9 - 0.3 + 0.6) / 3, 1e-12);
  EXPECT_NEAR(c.uses[1].credit, (-0.3 + 0.6 + 0.0) / 3, 1e-12);
  EXPECT_NEAR(c.uses[2].credit, (0.6 + 0.0 + 1.0) / 3, 1e-12);
  EXPECT_EQ(c.uses[1].outputs, chosen[1]);
  // A solved episode fills the missing rewards with the terminal one; an unsolved one averages.
  lib.end_episode(1.0);
  ASSERT_EQ(c.uses.size(), 5u);
  EXPECT_NEAR(c.uses[3].credit, (0.0 + 1.0 + 1.0) / 3, 1e-12);
  EXPECT_NEAR(c.uses[4].credit, (1.0 + 1.0 + 1.0) / 3, 1e-12);
  lib.begin_episode();
  lib.choose({0.1, 0.2, 0.3, 0.4}, rng);
  lib.reward(0.2);
  lib.choose({0.1, 0.2, 0.3, 0.4}, rng);
  lib.end_episode(SplittingCaseLibrary::kNoTerminal);
  ASSERT_EQ(c.uses.size(), 6u);  // the second choice saw no reward: dropped
  EXPECT_NEAR(c.uses[5].credit, 0.2, 1e-12);
}

// Credit that grows with output 1 everywhere: the case's output 1 climbs, the others stay near.
TEST(SplittingCases, AnOutputMovesAlongASignificantSlope) {
  SplittingCaseSettings s;
  s.horizon = 1;
  SplittingCaseLibrary lib(s, {0.5, 0.5, 0.5, 0.5});
  core::Rng rng(7), noise(8);
  lib.begin_episode();
  for (int i = 0; i < 400; ++i) {
    const CaseOutputs a = lib.choose({0.5, 0.5, 0.5, 0.5}, rng);
    lib.reward(std::clamp(a[1] - 0.5 + 0.05 * noise.uniform(-1, 1), -1.0, 1.0));
  }
  EXPECT_EQ(lib.size(), 1);
  EXPECT_GT(lib.at(0).outputs[1], 0.9);
  for (const int o : {0, 2, 3}) EXPECT_NEAR(lib.at(0).outputs[o], 0.5, 0.21) << o;
}

// Two situations (input 3 low or high) whose credit wants output 1 in opposite directions: the one
// case splits, along input 3, and each half's output 1 goes its own way.
TEST(SplittingCases, ACaseWhoseSituationsWantOppositeOutputsSplits) {
  SplittingCaseSettings s;
  s.horizon = 1;
  s.max_cases = 4;
  SplittingCaseLibrary lib(s, {0.5, 0.5, 0.5, 0.5});
  core::Rng rng(11), situation(12);
  lib.begin_episode();
  for (int i = 0; i < 1500; ++i) {
    const bool high = situation.uniform01() < 0.5;
    const CaseInputs in{0.5, 0.5, 0.5, high ? 0.9 : 0.1};
    const CaseOutputs a = lib.choose(in, rng);
    lib.reward(std::clamp((high ? 1.0 : -1.0) * (a[1] - 0.5) + 0.05 * situation.uniform(-1, 1), -1.0, 1.0));
  }
  ASSERT_GE(lib.splits(), 1);
  ASSERT_GE(lib.size(), 2);
  // The case nearest each situation recommends its own direction.
  auto nearest = [&](double input3) {
    int best = 0;
    for (int j = 1; j < lib.size(); ++j) {
      if (std::abs(lib.at(j).prototype[3] - input3) < std::abs(lib.at(best).prototype[3] - input3)) best = j;
    }
    return lib.at(best);
  };
  EXPECT_GT(nearest(0.9).outputs[1], 0.8);
  EXPECT_LT(nearest(0.1).outputs[1], 0.2);
}

TEST(SplittingCases, TheSameSeedGivesTheSameLibrary) {
  auto run = [] {
    SplittingCaseLibrary lib({}, {0.5, 0.5, 0.5, 0.5});
    core::Rng rng(3);
    lib.begin_episode();
    for (int i = 0; i < 300; ++i) {
      const CaseOutputs a = lib.choose({rng.uniform01(), 0.5, 0.5, rng.uniform01()}, rng);
      lib.reward(a[0] - a[2]);
    }
    return lib.at(0).outputs;
  };
  EXPECT_EQ(run(), run());
}

TEST(SplittingCases, BadSettingsAndValuesAreOneLineErrors) {
  auto fails = [](SplittingCaseSettings s, const char* name) {
    try {
      SplittingCaseLibrary lib(s, {0.5, 0.5, 0.5, 0.5});
      ADD_FAILURE() << name;
    } catch (const ParameterError& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
    }
  };
  SplittingCaseSettings s;
  s.horizon = 0;
  fails(s, "horizon");
  s = {};
  s.exploration = 0.0;
  fails(s, "exploration");
  s = {};
  s.window = 20;
  s.refit_every = 30;
  fails(s, "refit_every");
  s = {};
  s.max_cases = 0;
  fails(s, "max_cases");
  EXPECT_THROW(SplittingCaseLibrary({}, {0.5, 1.5, 0.5, 0.5}), ParameterError);
  SplittingCaseLibrary lib({}, {0.5, 0.5, 0.5, 0.5});
  core::Rng rng(1);
  EXPECT_THROW(lib.reward(1.5), ParameterError);
  EXPECT_THROW(lib.choose({0.5, 0.5, std::nan(""), 0.5}, rng), ParameterError);
  EXPECT_THROW(lib.end_episode(3.0), ParameterError);
}

}  // namespace
}  // namespace amp::learn
