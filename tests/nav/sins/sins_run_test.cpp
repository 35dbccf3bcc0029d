#include "amp/nav/sins/sins_run.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/core/rng.hpp"
#include "amp/learn/case_library.hpp"
#include "amp/nav/polygon_nav_world.hpp"
#include "amp/nav/sins/parameter_policy.hpp"
#include "support/sanitizer_build.hpp"

namespace amp::nav {
namespace {

using V = Eigen::Vector2d;

WorldOutcome outcome(bool solved, int steps, double distance, double optimal, int collisions, double ms) {
  WorldOutcome w;
  w.solved = solved;
  w.steps = steps;
  w.distance = distance;
  w.optimal = optimal;
  w.virtual_collisions = collisions;
  w.time_ms = ms;
  return w;
}

TEST(SinsEstimators, CumulativeAveragesByHand) {
  const std::vector<WorldOutcome> worlds{outcome(true, 40, 36.0, 30.0, 2, 1.0), outcome(false, 1000, 500.0, 32.0, 7, 9.0),
                                         outcome(true, 60, 48.0, 40.0, 0, 2.0)};
  const std::vector<Estimators> c = cumulative_estimates(worlds);
  ASSERT_EQ(c.size(), 3u);
  EXPECT_EQ(c[0].worlds, 1);
  EXPECT_DOUBLE_EQ(c[0].solved_fraction, 1.0);
  EXPECT_DOUBLE_EQ(c[0].distance_ratio_mean, 1.2);
  EXPECT_DOUBLE_EQ(c[1].solved_fraction, 0.5);
  EXPECT_DOUBLE_EQ(c[1].steps_mean, 520.0);
  EXPECT_DOUBLE_EQ(c[1].distance_ratio_mean, 1.2);  // over the solved worlds only
  const Estimators& e = c[2];
  EXPECT_DOUBLE_EQ(e.solved_fraction, 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(e.steps_mean, 1100.0 / 3.0);
  EXPECT_DOUBLE_EQ(e.distance_mean, 584.0 / 3.0);
  EXPECT_DOUBLE_EQ(e.distance_ratio_mean, (1.2 + 1.2) / 2.0);
  EXPECT_DOUBLE_EQ(e.virtual_collisions_mean, 3.0);
  EXPECT_DOUBLE_EQ(e.time_per_world_ms_mean, 4.0);
  EXPECT_EQ(estimate(worlds, 0).worlds, 0);
  EXPECT_EQ(estimate({outcome(false, 5, 1, 1, 0, 0)}, 1).distance_ratio_mean, 0.0);
}

SinsSettings exact_settings() {
  SinsSettings s;
  s.sensor_noise = 0.0;
  return s;
}

// An empty box: the static robot without noise goes straight at one metre a step.
TEST(SinsRunWorld, AnEmptyBoxIsCrossedInAStraightLine) {
  const SinsSettings s = exact_settings();
  const ClutterWorld w = assemble_clutter_world({}, V(2, 20), V(38, 20), s.world);
  StaticParameters policy(SchemaParameters{2.5, 1.0, 0.0, 10.0});
  core::Rng rng(1);
  WorldTrace trace;
  const WorldOutcome o = run_world(w, 0, policy, s, rng, nullptr, &trace);
  EXPECT_TRUE(o.solved);
  // After 35 steps the robot is 1 m short; the 36th step ends on the goal.
  EXPECT_EQ(o.steps, 36);
  EXPECT_NEAR(o.distance, 36.0, 1e-9);
  EXPECT_EQ(o.virtual_collisions, 0);
  EXPECT_EQ(o.blocked, 0);
  EXPECT_NEAR(o.min_clearance, 2.0 - 0.25, 1e-9);  // at the start, 2 m from the left wall
  ASSERT_EQ(trace.positions.size(), 37u);
  ASSERT_EQ(trace.parameters.size(), 36u);
  for (std::size_t i = 0; i < trace.positions.size(); ++i) {
    EXPECT_NEAR((trace.positions[i] - V(2.0 + static_cast<double>(i), 20)).norm(), 0.0, 1e-9) << i;
  }
}

TEST(SinsRunWorld, StopsAtTheStepLimitUnsolved) {
  SinsSettings s = exact_settings();
  s.step_limit = 10;
  const ClutterWorld w = assemble_clutter_world({}, V(2, 20), V(38, 20), s.world);
  StaticParameters policy(SchemaParameters{2.5, 1.0, 0.0, 10.0});
  core::Rng rng(1);
  const WorldOutcome o = run_world(w, 0, policy, s, rng);
  EXPECT_FALSE(o.solved);
  EXPECT_EQ(o.steps, 10);
  EXPECT_NEAR(o.distance, 10.0, 1e-9);
}

// Generated worlds, every system: every position is free for the disc, "solved" means the last
// step passed within the tolerance of the goal, and the counts agree with the trace.
TEST(SinsRunWorld, NeverPassesThroughAnObstacleAndReachesWhatItSays) {
  SinsSettings s;
  s.step_limit = 400;
  s.worlds = test::case_share(6);  // 2 worlds per system under the sanitizers
  for (const char* system : {"static", "random", "adaptive", "sins-plus"}) {
    auto policy = make_parameter_policy(system, {}, SchemaParameters::middle(), 0.3);
    ClutterWorldSequence sequence(17, s.world);
    core::Rng rng(3);
    for (int i = 0; i < s.worlds; ++i) {
      const ClutterWorld w = sequence.next();
      WorldTrace trace;
      const WorldOutcome o = run_world(w, i, *policy, s, rng, nullptr, &trace);
      ASSERT_EQ(trace.positions.size(), static_cast<std::size_t>(o.steps) + 1);
      for (const V& p : trace.positions) {
        ASSERT_TRUE(w.world->disc_free(p, s.world.robot_radius)) << system << " world " << i << " at " << p.transpose();
      }
      const V& last = trace.positions.back();
      const V& before = trace.positions[trace.positions.size() - 2];
      // Solved exactly when the last step's segment passes within the tolerance of the goal.
      const V ab = last - before;
      const double t = ab.squaredNorm() > 0 ? std::clamp((w.goal - before).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
      EXPECT_EQ(o.solved, (before + t * ab - w.goal).norm() <= s.goal_tolerance) << system << " world " << i;
      EXPECT_GE(o.min_clearance, 0.0);
      EXPECT_EQ(o.virtual_collisions > 0, o.min_clearance < s.virtual_collision_distance) << system << " world " << i;
      double driven = 0;
      for (std::size_t k = 1; k < trace.positions.size(); ++k) driven += (trace.positions[k] - trace.positions[k - 1]).norm();
      EXPECT_NEAR(o.distance, driven, 1e-9);
    }
  }
}

TEST(SinsRunSequence, TheSameSeedGivesTheSameRunAndEverySystemTheSameWorlds) {
  SinsSettings s;
  s.worlds = test::case_share(5);  // 2 worlds under the sanitizers
  s.step_limit = 300;
  auto run = [&](const char* system) {
    auto policy = make_parameter_policy(system, {}, SchemaParameters::middle(), 0.3);
    return run_sequence(*policy, s, 42);
  };
  const SequenceOutcome a = run("adaptive"), b = run("adaptive"), st = run("static");
  const SequenceOutcome plus = run("sins-plus"), plus_again = run("sins-plus");
  for (std::size_t i = 0; i < plus.worlds.size(); ++i) {
    EXPECT_EQ(plus.worlds[i].steps, plus_again.worlds[i].steps);
    EXPECT_EQ(plus.worlds[i].distance, plus_again.worlds[i].distance);
    EXPECT_EQ(plus.worlds[i].optimal, st.worlds[i].optimal);
  }
  ASSERT_EQ(a.worlds.size(), static_cast<std::size_t>(s.worlds));
  for (std::size_t i = 0; i < a.worlds.size(); ++i) {
    EXPECT_EQ(a.worlds[i].solved, b.worlds[i].solved);
    EXPECT_EQ(a.worlds[i].steps, b.worlds[i].steps);
    EXPECT_EQ(a.worlds[i].distance, b.worlds[i].distance);
    EXPECT_EQ(a.worlds[i].virtual_collisions, b.worlds[i].virtual_collisions);
    EXPECT_EQ(a.worlds[i].optimal, st.worlds[i].optimal);  // the same world for both systems
    EXPECT_EQ(a.worlds[i].clutter, st.worlds[i].clutter);
  }
  EXPECT_EQ(a.cases, b.cases);
  EXPECT_EQ(st.cases, 0);
}

TEST(SinsRunSequence, TheClutterChangesAtTheSetWorld) {
  SinsSettings s;
  s.worlds = 4;
  s.step_limit = 50;
  s.world.clutter = 0.1;
  s.change_at = 2;
  s.clutter_after = 0.3;
  StaticParameters policy;
  const SequenceOutcome o = run_sequence(policy, s, 7);
  ASSERT_EQ(o.worlds.size(), 4u);
  EXPECT_LT(o.worlds[0].clutter, 0.2);
  EXPECT_LT(o.worlds[1].clutter, 0.2);
  EXPECT_GE(o.worlds[2].clutter, 0.3);
  EXPECT_GE(o.worlds[3].clutter, 0.3);
}

TEST(SinsSettings, BadValuesAreNamedOnOneLine) {
  auto message = [](auto change) {
    SinsSettings s;
    change(s);
    try {
      s.validate();
    } catch (const ParameterError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message([](SinsSettings& s) { s.world.clutter = 0.0; }).find("clutter"), std::string::npos);
  EXPECT_NE(message([](SinsSettings& s) { s.world.clutter = 1.0; }).find("clutter"), std::string::npos);
  EXPECT_NE(message([](SinsSettings& s) { s.step_limit = 0; }).find("step_limit"), std::string::npos);
  EXPECT_NE(message([](SinsSettings& s) { s.control_interval = 0; }).find("control_interval"), std::string::npos);
  EXPECT_NE(message([](SinsSettings& s) { s.worlds = 0; }).find("worlds"), std::string::npos);
  EXPECT_NE(message([](SinsSettings& s) { s.change_at = 3, s.clutter_after = 1.0; }).find("clutter_after"),
            std::string::npos);
  EXPECT_NE(message([](SinsSettings& s) { s.stall_exploration = 2.0; }).find("stall_exploration"), std::string::npos);
  EXPECT_EQ(message([](SinsSettings&) {}), "no error");
  EXPECT_EQ(message([](SinsSettings& s) { s.step_limit = 0; }).find('\n'), std::string::npos);
}

TEST(SinsRunSequence, AClutterNoWorldCanHaveIsRefused) {
  SinsSettings s;
  s.worlds = 1;
  s.world.clutter = 0.95;
  s.world.max_tries = 3;
  StaticParameters policy;
  EXPECT_THROW(run_sequence(policy, s, 1), ParameterError);
}

// The named scales: the classic arena's lengths times the factor, the robot unchanged; the defaults
// are the calibrated scale's; an unknown name lists the valid ones.
TEST(SinsScale, NamedScalesSetTheWorldAndStepLimit) {
  SinsSettings s;
  EXPECT_DOUBLE_EQ(s.world.width, 40.0 * kCalibratedScale.factor);
  EXPECT_DOUBLE_EQ(s.world.max_radius, 2.0 * kCalibratedScale.factor);
  EXPECT_EQ(s.step_limit, kCalibratedScale.step_limit);
  s.set_scale(sins_scale("classic"));
  EXPECT_DOUBLE_EQ(s.world.width, 40.0);
  EXPECT_DOUBLE_EQ(s.world.height, 40.0);
  EXPECT_DOUBLE_EQ(s.world.min_radius, 0.5);
  EXPECT_DOUBLE_EQ(s.world.max_radius, 2.0);
  EXPECT_DOUBLE_EQ(s.world.robot_radius, 0.25);
  EXPECT_EQ(s.step_limit, 1000);
  try {
    sins_scale("huge");
    FAIL() << "no error";
  } catch (const ParameterError& e) {
    EXPECT_NE(std::string(e.what()).find("(valid: calibrated, classic)"), std::string::npos) << e.what();
  }
}

// Worlds drawn at once and run give run_sequence's outcomes, across a change of clutter.
TEST(SinsSequence, PreDrawnWorldsGiveTheStreamingOutcomes) {
  SinsSettings s;
  s.worlds = 5;
  s.step_limit = 150;
  s.change_at = 3;
  s.clutter_after = 0.35;
  const auto stream = make_parameter_policy("adaptive", learn::CaseSettings{}, SchemaParameters::middle(), 0.5);
  const auto drawn = make_parameter_policy("adaptive", learn::CaseSettings{}, SchemaParameters::middle(), 0.5);
  const SequenceOutcome a = run_sequence(*stream, s, 11);
  const SequenceWorlds worlds = draw_sequence_worlds(s, 11);
  const SequenceOutcome b = run_sequence(*drawn, s, 11, worlds);
  ASSERT_EQ(a.worlds.size(), b.worlds.size());
  for (std::size_t i = 0; i < a.worlds.size(); ++i) {
    EXPECT_EQ(a.worlds[i].steps, b.worlds[i].steps) << i;
    EXPECT_EQ(a.worlds[i].solved, b.worlds[i].solved) << i;
    EXPECT_DOUBLE_EQ(a.worlds[i].distance, b.worlds[i].distance) << i;
    EXPECT_DOUBLE_EQ(a.worlds[i].clutter, b.worlds[i].clutter) << i;
  }
  EXPECT_GE(b.worlds[3].clutter, 0.35);
  EXPECT_EQ(a.rejected_worlds, b.rejected_worlds);
  EXPECT_EQ(a.cases, b.cases);
}

// The hooks: on_world sees every outcome in order, last_trace gets the last world's drive, which
// starts at its start and ends where its outcome says (within the goal tolerance when solved).
TEST(SinsSequence, HooksSeeEveryWorldAndTheLastTrace) {
  SinsSettings s;
  s.worlds = 4;
  s.step_limit = 200;
  const SequenceWorlds worlds = draw_sequence_worlds(s, 5);
  const auto policy = make_parameter_policy("random", learn::CaseSettings{}, SchemaParameters::middle(), 0.5);
  std::vector<int> seen;
  WorldTrace trace;
  SequenceHooks hooks;
  hooks.on_world = [&seen](const WorldOutcome& w) { seen.push_back(w.index); };
  hooks.last_trace = &trace;
  const SequenceOutcome out = run_sequence(*policy, s, 5, worlds, hooks);
  EXPECT_EQ(seen, (std::vector<int>{0, 1, 2, 3}));
  ASSERT_EQ(trace.positions.size(), static_cast<std::size_t>(out.worlds.back().steps) + 1);
  EXPECT_TRUE(trace.positions.front().isApprox(worlds.worlds.back().start));
  if (out.worlds.back().solved) {
    EXPECT_LE((trace.positions.back() - worlds.worlds.back().goal).norm(), s.goal_tolerance + 1.0);
  }
  // The trace changes nothing: the same run without hooks gives the same outcomes.
  const auto again = make_parameter_policy("random", learn::CaseSettings{}, SchemaParameters::middle(), 0.5);
  const SequenceOutcome plain = run_sequence(*again, s, 5, worlds);
  for (std::size_t i = 0; i < out.worlds.size(); ++i) EXPECT_EQ(out.worlds[i].steps, plain.worlds[i].steps) << i;
}

// A clutter no world can be drawn at, after the change: the error says which world and that it
// came after the change, so that `amp sins` can name --param clutter_after.
TEST(SinsSequence, ADrawErrorSaysWhetherItCameAfterTheChange) {
  SinsSettings s;
  s.worlds = 3;
  s.change_at = 2;
  s.clutter_after = 0.95;
  s.world.max_tries = 3;
  try {
    draw_sequence_worlds(s, 1);
    FAIL() << "expected SequenceDrawError";
  } catch (const SequenceDrawError& e) {
    EXPECT_TRUE(e.after_change());
    EXPECT_EQ(std::string(e.what()).rfind("world 3: ", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace amp::nav
