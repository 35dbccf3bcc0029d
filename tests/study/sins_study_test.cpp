#include "amp/study/sins_study.hpp"

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/nav/sins/parameter_policy.hpp"

namespace amp::study {
namespace {

SinsSetup small_setup() {
  SinsSetup setup;
  read_sins_params({{"worlds", core::ParamValue(4.0)}, {"step_limit", core::ParamValue(150.0)}},
                   nav::kCalibratedScale, setup);
  setup.seed = 9;
  return setup;
}

// Every system of the study is nav::run_sequence on the same worlds: the one sequence loop.
TEST(SinsStudy, EverySystemIsTheStreamingSequence) {
  const SinsSetup setup = small_setup();
  const SinsResult r = run_sins(setup, true);
  ASSERT_EQ(r.runs.size(), 3u);
  EXPECT_EQ(r.runs[0].system, "adaptive");
  for (const SystemRun& run : r.runs) {
    const auto policy = nav::make_parameter_policy(run.system, setup.cases, setup.initial,
                                                   setup.sins.stall_exploration, setup.plus);
    const nav::SequenceOutcome expected = nav::run_sequence(*policy, setup.sins, setup.seed);
    ASSERT_EQ(run.worlds.size(), expected.worlds.size()) << run.system;
    for (std::size_t i = 0; i < run.worlds.size(); ++i) {
      EXPECT_EQ(run.worlds[i].steps, expected.worlds[i].steps) << run.system << " " << i;
      EXPECT_EQ(run.worlds[i].distance, expected.worlds[i].distance) << run.system << " " << i;
    }
    EXPECT_EQ(run.cases, expected.cases);
    EXPECT_EQ(r.rejected_worlds, expected.rejected_worlds);
    EXPECT_EQ(run.last_trace.positions.size(), static_cast<std::size_t>(run.worlds.back().steps) + 1);
  }
  const nlohmann::ordered_json record = sins_record(setup, r);
  EXPECT_EQ(record.at("world_outcomes").size(), 4u);
  EXPECT_EQ(record.at("settings").at("worlds"), 4);
  EXPECT_EQ(record.at("systems").size(), 3u);
}

TEST(SinsStudy, ParamsRouteToEverySchemaAndTheScaleFillsTheRest) {
  SinsSetup setup;
  read_sins_params({{"max_cases", core::ParamValue(6.0)}, {"goal_gain", core::ParamValue(1.5)}},
                   nav::kClassicScale, setup);
  EXPECT_EQ(setup.cases.max_cases, 6);
  EXPECT_EQ(setup.plus.max_cases, 6);
  EXPECT_DOUBLE_EQ(setup.initial.goal_gain, 1.5);
  EXPECT_EQ(setup.sins.step_limit, nav::kClassicScale.step_limit);
  EXPECT_DOUBLE_EQ(setup.sins.world.width, 40.0);
  EXPECT_THROW(read_sins_params({{"nope", core::ParamValue(1.0)}}, nav::kClassicScale, setup), ParameterError);
}

}  // namespace
}  // namespace amp::study
