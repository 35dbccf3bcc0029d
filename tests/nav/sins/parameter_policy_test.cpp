#include "amp/nav/sins/parameter_policy.hpp"

#include <algorithm>
#include <array>
#include <vector>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/core/rng.hpp"

namespace amp::nav {
namespace {

void expect_same(const SchemaParameters& a, const SchemaParameters& b) {
  EXPECT_EQ(a.obstacle_gain, b.obstacle_gain);
  EXPECT_EQ(a.goal_gain, b.goal_gain);
  EXPECT_EQ(a.noise_gain, b.noise_gain);
  EXPECT_EQ(a.noise_persistence, b.noise_persistence);
}

TEST(StaticParameters, KeepsItsParametersAndDrawsNothing) {
  SchemaParameters p{1.5, 0.5, 1.0, 5.0};
  StaticParameters s(p);
  core::Rng rng(3), untouched(3);
  expect_same(s.begin_world(rng), p);
  for (int i = 0; i < 10; ++i) expect_same(s.end_interval({0.1, 0.9, 0.5, 0.2}, rng), p);
  EXPECT_EQ(rng.uniform01(), untouched.uniform01());
  EXPECT_EQ(s.cases(), 0);
  EXPECT_THROW(StaticParameters(SchemaParameters{6.0, 1.0, 0.5, 10.0}), ParameterError);
}

TEST(RandomParameters, DrawsEveryParameterUniformlyOverItsRange) {
  RandomParameters r;
  core::Rng rng(11), mirror(11);
  double lo[4] = {1e9, 1e9, 1e9, 1e9}, hi[4] = {-1e9, -1e9, -1e9, -1e9};
  for (int i = 0; i < 2000; ++i) {
    const SchemaParameters p = i == 0 ? r.begin_world(rng) : r.end_interval({0.5, 0.5, 0.5, 0.5}, rng);
    // The same four draws, in order, by hand.
    const double u0 = mirror.uniform(0, 5), u1 = mirror.uniform(0, 2), u2 = mirror.uniform(0, 1),
                 u3 = mirror.uniform(1, 20);
    ASSERT_EQ(p.obstacle_gain, u0);
    ASSERT_EQ(p.goal_gain, u1);
    ASSERT_EQ(p.noise_gain, u2);
    ASSERT_EQ(p.noise_persistence, u3);
    const double v[4] = {p.obstacle_gain, p.goal_gain, p.noise_gain, p.noise_persistence};
    for (int k = 0; k < 4; ++k) lo[k] = std::min(lo[k], v[k]), hi[k] = std::max(hi[k], v[k]);
  }
  // 2000 uniform draws come within 1% of both ends of each range.
  const double a[4] = {0, 0, 0, 1}, b[4] = {5, 2, 1, 20};
  for (int k = 0; k < 4; ++k) {
    EXPECT_LT(lo[k] - a[k], 0.01 * (b[k] - a[k])) << k;
    EXPECT_LT(b[k] - hi[k], 0.01 * (b[k] - a[k])) << k;
  }
}

// The first cycle of SINS by hand: one generic case (all 0.5), a history of one sample.
TEST(CaseBasedParameters, FirstCycleByHand) {
  learn::CaseSettings cs;  // case length 4, learning rate 0.5
  const SchemaParameters initial = SchemaParameters::middle();
  CaseBasedParameters sins(cs, initial, 0.3);
  core::Rng rng(5), mirror(5);
  expect_same(sins.begin_world(rng), initial);
  const learn::CaseInputs in{0.3, 0.9, 0.6, 0.7};
  const SchemaParameters next = sins.end_interval(in, rng);

  // Retrieve: every alignment overlaps the one sample; E = mean of (in - 0.5)^2 = (.04 + .16 +
  // .01 + .04) / 4 = .0625, ties go to the first of the sweep, p = 4.
  ASSERT_TRUE(sins.last_cycle().has_value());
  const CaseCycle& c = *sins.last_cycle();
  EXPECT_EQ(c.match.case_index, 0);
  EXPECT_EQ(c.match.position, 4);
  EXPECT_EQ(c.match.overlap, 1);
  EXPECT_NEAR(c.match.error, 0.0625, 1e-15);
  // Adapt: the case's last sample (0.5) plus spread * u. Progress r = 2 (0.7 - 0.5) = 0.4, so the
  // spread is max(sqrt(.0625), 0.3 (1 - 0.4)) = max(.25, .18) = .25.
  const double spread = 0.25;
  const double u[4] = {mirror.uniform(-1, 1), mirror.uniform(-1, 1), mirror.uniform(-1, 1), mirror.uniform(-1, 1)};
  const SchemaParameters expected = SchemaParameters::from_normalised(
      {0.5 + spread * u[0], 0.5 + spread * u[1], 0.5 + spread * u[2], 0.5 + spread * u[3]});
  EXPECT_NEAR(next.obstacle_gain, expected.obstacle_gain, 1e-12);
  EXPECT_NEAR(next.goal_gain, expected.goal_gain, 1e-12);
  EXPECT_NEAR(next.noise_gain, expected.noise_gain, 1e-12);
  EXPECT_NEAR(next.noise_persistence, expected.noise_persistence, 1e-12);
  // Learn: first use, relative similarity 1: reinforced. Case sample 3 moves halfway to the input;
  // its outputs move toward the parameters that were in use (the middle, 0.5): no change.
  EXPECT_EQ(c.learned, learn::Learned::kReinforced);
  EXPECT_EQ(c.relative_similarity, 1.0);
  const learn::Case& case0 = sins.library().at(0);
  for (int x = 0; x < 4; ++x) EXPECT_NEAR(case0.inputs[3][x], 0.5 + 0.5 * (in[x] - 0.5), 1e-15) << x;
  for (int x = 0; x < 4; ++x) EXPECT_NEAR(case0.outputs[3][x], 0.5, 1e-15) << x;
  EXPECT_EQ(case0.uses, 1);
  EXPECT_EQ(sins.history().size(), 1);
  EXPECT_NEAR(sins.history().reward(0), 0.4, 1e-15);
}

TEST(CaseBasedParameters, ANewWorldStartsFromTheInitialParametersAndKeepsTheCases) {
  learn::CaseSettings cs;
  cs.max_cases = 4;
  const SchemaParameters initial{1.0, 1.5, 0.25, 4.0};
  CaseBasedParameters sins(cs, initial);
  core::Rng rng(8);
  sins.begin_world(rng);
  for (int i = 0; i < 40; ++i) sins.end_interval({i % 2 ? 0.9 : 0.05, 0.1, 0.5, 0.45}, rng);
  const int cases = sins.cases();
  const int uses = sins.library().at(0).uses;
  expect_same(sins.begin_world(rng), initial);
  EXPECT_EQ(sins.history().size(), 0);
  EXPECT_EQ(sins.cases(), cases);
  EXPECT_EQ(sins.library().at(0).uses, uses);
}

TEST(CaseBasedParameters, ThePapersRuleWithoutTheAdditions) {
  // stall_exploration 0 and reward_weighted off: a perfect match explores nothing and a reinforced
  // case's outputs move toward the parameters in use by the full rate.
  learn::CaseSettings cs;
  cs.reward_weighted = false;
  CaseBasedParameters sins(cs, SchemaParameters::middle(), 0.0);
  core::Rng rng(1);
  sins.begin_world(rng);
  const SchemaParameters p = sins.end_interval({0.5, 0.5, 0.5, 0.5}, rng);  // E = 0, no progress
  expect_same(p, SchemaParameters::from_normalised({0.5, 0.5, 0.5, 0.5}));
}

TEST(CaseBasedParameters, TheFirstCaseRecommendsTheInitialParameters) {
  // "SINS would also start out with those same settings": the generic case's outputs are the
  // initial parameters, so an exact match (no exploration) installs them again.
  const SchemaParameters initial{0.5, 0.5, 1.0, 10.0};
  CaseBasedParameters sins(learn::CaseSettings{}, initial, 0.0);
  for (const auto& out : sins.library().at(0).outputs) {
    for (int x = 0; x < 4; ++x) EXPECT_EQ(out[x], initial.normalised()[x]);
  }
  core::Rng rng(1);
  sins.begin_world(rng);
  const SchemaParameters p = sins.end_interval({0.5, 0.5, 0.5, 0.5}, rng);  // E = 0
  EXPECT_NEAR(p.obstacle_gain, initial.obstacle_gain, 1e-12);
  EXPECT_NEAR(p.goal_gain, initial.goal_gain, 1e-12);
  EXPECT_NEAR(p.noise_gain, initial.noise_gain, 1e-12);
  EXPECT_NEAR(p.noise_persistence, initial.noise_persistence, 1e-9);
}

TEST(CaseBasedParameters, OutcomeCreditByHand) {
  // Two worlds. The first (unsolved, R = 0) only sets the baseline b = 0. In the second, two
  // intervals install outputs from the generic case; it is solved at 20% of the step limit, so
  // R = 0.8, the advantage 0.8 - 0 and every sample used moves toward the mean of what was
  // installed from it by outcome_rate x 0.8 = 0.4; then b = 0 + 0.1 x 0.8.
  learn::CaseSettings cs;
  cs.outcome_rate = 0.5;
  CaseBasedParameters sins(cs, SchemaParameters::middle(), 0.3);
  core::Rng rng(5);
  sins.begin_world(rng);
  sins.end_interval({0.2, 0.6, 0.4, 0.5}, rng);
  sins.end_world(false, 1.0);
  EXPECT_EQ(sins.baseline(), 0.0);
  for (const auto& out : sins.library().at(0).outputs) {
    for (double v : out) EXPECT_EQ(v, 0.5);  // advantage 0: nothing moved
  }
  sins.begin_world(rng);
  std::array<learn::CaseOutputs, 4> sum{};
  std::array<int, 4> count{};
  for (int i = 0; i < 2; ++i) {
    const learn::CaseOutputs installed = sins.end_interval({0.3, 0.5, 0.5, 0.6}, rng).normalised();
    ASSERT_EQ(sins.last_cycle()->match.case_index, 0);
    const int q = std::min(sins.last_cycle()->match.position, 3);
    for (int x = 0; x < 4; ++x) sum[static_cast<std::size_t>(q)][x] += installed[x];
    ++count[static_cast<std::size_t>(q)];
  }
  ASSERT_EQ(sins.cases(), 1);
  const std::vector<learn::CaseOutputs> before = sins.library().at(0).outputs;
  sins.end_world(true, 0.2);
  EXPECT_NEAR(sins.baseline(), 0.08, 1e-15);
  for (std::size_t q = 0; q < 4; ++q) {
    for (int x = 0; x < 4; ++x) {
      const double want = count[q] == 0 ? before[q][x] : before[q][x] + 0.4 * (sum[q][x] / count[q] - before[q][x]);
      EXPECT_NEAR(sins.library().at(0).outputs[q][x], want, 1e-12) << "sample " << q << " output " << x;
    }
  }
}

TEST(ParameterPolicyFactory, NamesTheSystems) {
  EXPECT_EQ(make_parameter_policy("static", {}, SchemaParameters::middle(), 0.3)->name(), "static");
  EXPECT_EQ(make_parameter_policy("random", {}, SchemaParameters::middle(), 0.3)->name(), "random");
  EXPECT_EQ(make_parameter_policy("adaptive", {}, SchemaParameters::middle(), 0.3)->name(), "adaptive");
  EXPECT_EQ(make_parameter_policy("sins", {}, SchemaParameters::middle(), 0.3)->name(), "adaptive");
  EXPECT_EQ(make_parameter_policy("sins-plus", {}, SchemaParameters::middle(), 0.3)->name(), "sins-plus");
  try {
    make_parameter_policy("greedy", {}, SchemaParameters::middle(), 0.3);
    FAIL();
  } catch (const ParameterError& e) {
    EXPECT_EQ(std::string(e.what()), "unknown system 'greedy' (systems: static, random, adaptive, sins-plus)");
  }
  EXPECT_THROW(make_parameter_policy("adaptive", {}, SchemaParameters::middle(), 1.5), ParameterError);
  learn::CaseSettings bad;
  bad.max_cases = 0;
  EXPECT_THROW(make_parameter_policy("adaptive", bad, SchemaParameters::middle(), 0.3), ParameterError);
  learn::SplittingCaseSettings bad_plus;
  bad_plus.horizon = 0;
  EXPECT_THROW(make_parameter_policy("sins-plus", {}, SchemaParameters::middle(), 0.3, bad_plus), ParameterError);
}

}  // namespace
}  // namespace amp::nav
