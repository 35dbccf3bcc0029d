// bench::calibrate_sins_scale on short sequences: each factor's step limit is the random system's
// quantile read independently from nav::run_sequence, the check is real runs at the chosen scale
// on the fresh sequences (so the result repeats: every figure is recomputed from its seed through
// another code path and must be equal), and targets no scale reaches are one line.
#include "amp/bench/sins_calibration.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/core/rng.hpp"
#include "amp/learn/case_library.hpp"
#include "amp/nav/sins/parameter_policy.hpp"

namespace amp::bench {
namespace {

using ::testing::HasSubstr;

SinsCalibrationSettings quick() {
  SinsCalibrationSettings c;
  c.base.worlds = 12;
  c.search_sequences = 1;
  c.limit_sequences = 2;
  c.sequences = 3;
  c.bisections = 1;
  c.factor_low = 1.0;
  c.factor_high = 2.0;
  c.probe_step_limit = 1500;
  c.seed = 77;
  return c;
}

nav::SinsSettings at(const SinsCalibrationSettings& c, double factor, int step_limit) {
  nav::SinsSettings s = c.base;
  s.set_scale({"t", factor, step_limit, ""});
  return s;
}

nav::SequenceOutcome drive(const char* system, const nav::SinsSettings& s, std::uint64_t seed) {
  const auto policy = nav::make_parameter_policy(system, learn::CaseSettings{}, nav::SchemaParameters::middle(),
                                                 s.stall_exploration);
  return nav::run_sequence(*policy, s, seed);  // the streaming run, drawing its own worlds
}

double share(const nav::SequenceOutcome& r) {
  return static_cast<double>(std::count_if(r.worlds.begin(), r.worlds.end(), [](const auto& w) { return w.solved; })) /
         static_cast<double>(r.worlds.size());
}

// The least limit at which the random system solves the target share, by sorting the solved
// worlds' steps of a run at the probe limit.
int quantile_limit(const SinsCalibrationSettings& c, double factor, int first, int count) {
  std::vector<int> steps;
  int total = 0;
  for (int i = first; i < first + count; ++i) {
    const auto run = drive("random", at(c, factor, c.probe_step_limit), core::derive_seed(c.seed, i));
    total += static_cast<int>(run.worlds.size());
    for (const auto& w : run.worlds) {
      if (w.solved) steps.push_back(w.steps);
    }
  }
  std::sort(steps.begin(), steps.end());
  const auto need = static_cast<std::size_t>(std::ceil(c.random_target * total - 1e-9));
  return need <= steps.size() ? steps[need - 1] : -1;
}

TEST(SinsCalibration, ProbesAndCheckEqualIndependentRuns) {
  SinsCalibrationSettings c = quick();
  // Targets this small sample brackets between the bracket's ends (measured on seed 77: 0% at 1, 16.7% at 2 with GCC;
  // a clang build's simulation differs in rounding, and its shares bracket 10% too).
  c.static_target = 0.1;
  const SinsCalibration r = calibrate_sins_scale(c);
  ASSERT_TRUE(r.why.empty() || r.scale.step_limit > 0) << r.why;
  ASSERT_EQ(r.probes.size(), 4u) << r.why;  // both ends, one bisection, the check's own limit
  EXPECT_DOUBLE_EQ(r.probes[0].factor, c.factor_low);
  EXPECT_DOUBLE_EQ(r.probes[1].factor, c.factor_high);
  EXPECT_DOUBLE_EQ(r.probes[2].factor, 0.5 * (c.factor_low + c.factor_high));
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(r.probes[i].step_limit, quantile_limit(c, r.probes[i].factor, 0, c.search_sequences)) << i;
    EXPECT_GE(r.probes[i].random_solved, c.random_target) << i;
    const auto stat = drive("static", at(c, r.probes[i].factor, r.probes[i].step_limit), core::derive_seed(c.seed, 0));
    EXPECT_DOUBLE_EQ(r.probes[i].static_solved, share(stat)) << i;
  }
  EXPECT_EQ(r.scale.step_limit, quantile_limit(c, r.scale.factor, c.search_sequences, c.limit_sequences));
  EXPECT_DOUBLE_EQ(r.scale.factor, r.probes[3].factor);
  EXPECT_NEAR(std::fmod(r.scale.factor / c.factor_step, 1.0), 0.0, 1e-6);
  ASSERT_EQ(r.static_share.per_sequence.size(), static_cast<std::size_t>(c.sequences));
  for (int i = 0; i < c.sequences; ++i) {
    const std::uint64_t seed = core::derive_seed(c.seed, c.search_sequences + c.limit_sequences + i);
    const nav::SinsSettings s = at(c, r.scale.factor, r.scale.step_limit);
    EXPECT_DOUBLE_EQ(r.static_share.per_sequence[i], share(drive("static", s, seed))) << i;
    EXPECT_DOUBLE_EQ(r.random_share.per_sequence[i], share(drive("random", s, seed))) << i;
  }
  EXPECT_LE(r.static_share.ci95_low, r.static_share.mean);
  EXPECT_GE(r.static_share.ci95_high, r.static_share.mean);
  EXPECT_EQ(r.reached, r.static_share.holds(c.static_target) && r.random_share.holds(c.random_target));
  EXPECT_EQ(r.reached, r.why.empty()) << r.why;

}

TEST(SinsCalibration, TargetOutsideTheBracketIsOneLine) {
  SinsCalibrationSettings c = quick();
  c.static_target = 0.99;
  c.bisections = 0;
  const SinsCalibration r = calibrate_sins_scale(c);
  EXPECT_FALSE(r.reached);
  EXPECT_THAT(r.why, HasSubstr("its target 99.0% is not between"));
  EXPECT_EQ(r.why.find('\n'), std::string::npos);
  EXPECT_EQ(r.probes.size(), 2u);  // the two ends only: nothing is checked
  EXPECT_TRUE(r.static_share.per_sequence.empty());
}

TEST(SinsCalibration, RandomThatCannotReachItsShareIsOneLine) {
  SinsCalibrationSettings c = quick();
  c.probe_step_limit = 5;  // no world is crossed in five steps
  const SinsCalibration r = calibrate_sins_scale(c);
  EXPECT_FALSE(r.reached);
  EXPECT_THAT(r.why, HasSubstr("the random system solves 0.0% within 5 steps"));
}

TEST(SinsCalibration, BadSettingsAreRefused) {
  SinsCalibrationSettings c = quick();
  c.random_target = 1.5;
  EXPECT_THROW(calibrate_sins_scale(c), ParameterError);
  c = quick();
  c.factor_high = 0.5;
  EXPECT_THROW(calibrate_sins_scale(c), ParameterError);
  c = quick();
  c.sequences = 0;
  EXPECT_THROW(calibrate_sins_scale(c), ParameterError);
}

}  // namespace
}  // namespace amp::bench
