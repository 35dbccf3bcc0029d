// SinsNavigator: SINS's three systems as navigation methods, one run a whole sequence of clutter
// worlds in the problem's empty box.
#include "amp/nav/sins/sins_navigator.hpp"

#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/core/rng.hpp"
#include "amp/nav/sins/parameter_policy.hpp"
#include "amp/nav/sins/sins_run.hpp"
#include "amp/nav/navigator_catalog.hpp"
#include "support/bundled_problems.hpp"
#include "support/sanitizer_build.hpp"

namespace amp::nav {
namespace {

const core::ParamMap kSmall = {{"worlds", core::ParamValue(3.0)}, {"step_limit", core::ParamValue(200.0)}};
constexpr double kNoTimeLimit = 600.0;
// SameSeedGivesTheSameRecord's sequences: one world each under the sanitizers, the three of kSmall
// otherwise.
constexpr int kSameSeedWorlds = test::kSanitizerBuild ? 1 : 3;

TEST(SinsNavigator, TheSystemsAreRegistered) {
  for (const char* name : {"static", "random", "sins", "sins-plus"}) {
    ASSERT_TRUE(builtin_navigators().contains(name)) << name;
    EXPECT_NE(builtin_navigators().info(name).help.find("Ram & Santamaria 1993"), std::string::npos) << name;
  }
  auto has = [](const char* method, const char* param) {
    for (const core::ParamSpec& s : builtin_navigators().info(method).params) {
      if (s.name == param) return true;
    }
    return false;
  };
  EXPECT_TRUE(has("sins", "max_cases"));
  EXPECT_TRUE(has("sins", "obstacle_gain"));
  EXPECT_TRUE(has("static", "obstacle_gain"));
  EXPECT_FALSE(has("static", "max_cases"));
  EXPECT_FALSE(has("random", "obstacle_gain"));  // the random system draws its own
  for (const char* name : {"static", "random", "sins", "sins-plus"}) EXPECT_TRUE(has(name, "control_interval")) << name;
  EXPECT_TRUE(has("sins-plus", "horizon"));
  EXPECT_TRUE(has("sins-plus", "max_cases"));
  EXPECT_TRUE(has("sins-plus", "obstacle_gain"));  // where it starts
  EXPECT_FALSE(has("sins-plus", "case_length"));   // SINS's, not sins-plus's
  EXPECT_FALSE(has("sins", "horizon"));
}

TEST(SinsNavigator, SameSeedGivesTheSameRecord) {
  const world::Problem& arena = test::bundled_problem("sins-arena.yaml");
  core::ParamMap small = kSmall;
  small.insert_or_assign("worlds", core::ParamValue(static_cast<double>(kSameSeedWorlds)));
  for (const char* method : {"static", "random", "sins", "sins-plus"}) {
    SCOPED_TRACE(method);
    const NavigationOutcome a = execute_navigation(arena, method, small, 7, kNoTimeLimit);
    const NavigationOutcome b = execute_navigation(arena, method, small, 7, kNoTimeLimit);
    const NavigationOutcome c = execute_navigation(arena, method, small, 8, kNoTimeLimit);
    EXPECT_EQ(a.record.status, core::PlanStatus::kSolved) << a.record.message;
    EXPECT_EQ(a.record.extra, b.record.extra);
    EXPECT_EQ(a.record.path_length, b.record.path_length);
    EXPECT_NE(a.record.path_length, c.record.path_length);
    EXPECT_GT(a.record.path_length, 0.0);
    EXPECT_EQ(a.record.extra.at("worlds"), static_cast<double>(kSameSeedWorlds));
    for (const char* key : {"solved_fraction", "steps_mean", "distance_mean", "distance_ratio_mean",
                            "virtual_collisions_mean", "cases", "rejected_worlds"}) {
      EXPECT_EQ(a.record.extra.count(key), 1u) << key;
    }
    EXPECT_LE(a.record.extra.at("steps_mean"), 200.0);
    EXPECT_TRUE(a.trace.empty());
  }
  EXPECT_GE(execute_navigation(arena, "sins", small, 7, kNoTimeLimit).record.extra.at("cases"), 1.0);
  EXPECT_EQ(execute_navigation(arena, "static", small, 7, kNoTimeLimit).record.extra.at("cases"), 0.0);
}

// A run is run_sequence with the run's settings (every one passed on) and the first draw of
// Rng(seed) as the sequence's seed.
TEST(SinsNavigator, ARunIsTheSequenceWithItsSettings) {
  const world::Problem& arena = test::bundled_problem("sins-arena.yaml");
  core::ParamMap params = kSmall;
  params.emplace("stall_exploration", core::ParamValue(0.8));
  params.emplace("control_interval", core::ParamValue(6.0));
  params.emplace("goal_gain", core::ParamValue(1.5));
  const NavigationOutcome got = execute_navigation(arena, "sins", params, 11, kNoTimeLimit);
  SinsSettings s;
  s.worlds = 3;
  s.step_limit = 200;
  s.stall_exploration = 0.8;
  s.control_interval = 6;
  SchemaParameters initial = SchemaParameters::middle();
  initial.goal_gain = 1.5;
  CaseBasedParameters policy(learn::CaseSettings{}, initial, 0.8);
  const SequenceOutcome expected = run_sequence(policy, s, core::Rng(11).next_u64());
  const Estimators e = estimate(expected.worlds, expected.worlds.size());
  EXPECT_EQ(got.record.extra.at("steps_mean"), e.steps_mean);
  EXPECT_EQ(got.record.extra.at("distance_mean"), e.distance_mean);
  EXPECT_EQ(got.record.extra.at("cases"), expected.cases);
}

TEST(SinsNavigator, StopFiringEndsTheSequenceAsATimeout) {
  const std::atomic<bool> cancel{true};
  const NavigationOutcome o = execute_navigation(test::bundled_problem("sins-arena.yaml"), "sins", kSmall, 7,
                                                 kNoTimeLimit, builtin_navigators(), &cancel);
  EXPECT_EQ(o.record.status, core::PlanStatus::kTimeout);
  EXPECT_LT(o.record.extra.at("worlds"), 3.0);
}

void expect_refused(const world::Problem& problem, const std::string& words) {
  try {
    execute_navigation(problem, "sins", kSmall, 1, kNoTimeLimit);
    FAIL() << problem.name << " was accepted";
  } catch (const ParameterError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find(problem.name), std::string::npos) << m;  // names the problem
    EXPECT_NE(m.find(words), std::string::npos) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  }
}

TEST(SinsNavigator, AProblemWithObstaclesIsRefused) {
  expect_refused(test::bundled_problem("office-polygons.yaml"), "the problem must be an empty box");
  expect_refused(test::bundled_problem("office-map.yaml"), "the problem must be an empty box");
}

// Refused for its kind (NavWorld::as_polygons is null), though it is empty and at the origin.
TEST(SinsNavigator, AnEmptyMapIsRefused) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("amp-sins-navigator-map-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  {
    std::ofstream map(dir / "empty.map");
    map << "type octile\nheight 40\nwidth 40\nmap\n";
    for (int row = 0; row < 40; ++row) map << std::string(40, '.') << "\n";
  }
  std::ofstream(dir / "empty.yaml") << "name: EmptyMap\nworld:\n  map: empty.map\n"
                                    << "robot: {type: disc, radius: 0.25}\nstart: [3, 20]\ngoal: [37, 20]\n";
  const world::Problem empty = world::load_problem(dir / "empty.yaml");
  expect_refused(empty, "the problem must be an empty box");
  std::filesystem::remove_all(dir);
}

TEST(SinsNavigator, BoundsAwayFromTheOriginOrTooSmallAreRefused) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("amp-sins-navigator-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "shifted.yaml") << "name: Shifted\nbounds: {min: [1, 0], max: [41, 40]}\n"
                                      << "robot: {type: disc, radius: 0.25}\nstart: [3, 20]\ngoal: [39, 20]\n";
  std::ofstream(dir / "tiny.yaml") << "name: Tiny\nbounds: {min: [0, 0], max: [1, 1]}\n"
                                   << "robot: {type: disc, radius: 0.25}\nstart: [0.3, 0.5]\ngoal: [0.7, 0.5]\n";
  const world::Problem shifted = world::load_problem(dir / "shifted.yaml");
  const world::Problem tiny = world::load_problem(dir / "tiny.yaml");
  expect_refused(shifted, "[0, 0]");
  expect_refused(tiny, "problem 'Tiny'");
  std::filesystem::remove_all(dir);  // only now: the navigation task reads the file's events
}

TEST(SinsNavigator, BadParametersThrow) {
  const auto make = [](const char* method, const char* name, double value) {
    builtin_navigators().make(method, {{name, core::ParamValue(value)}});
  };
  EXPECT_THROW(make("sins", "clutter", 0.0), ParameterError);
  EXPECT_THROW(make("static", "clutter", 1.0), ParameterError);
  EXPECT_THROW(make("random", "control_interval", 0.0), ParameterError);
  EXPECT_THROW(make("sins", "max_cases", 0.0), ParameterError);
  EXPECT_THROW(make("sins", "obstacle_gain", 9.0), ParameterError);
  EXPECT_THROW(make("static", "obstacle_gain", 9.0), ParameterError);
  EXPECT_THROW(make("static", "max_cases", 4.0), ParameterError);  // not a parameter of the static system
  EXPECT_NO_THROW(make("sins", "max_cases", 4.0));
}

}  // namespace
}  // namespace amp::nav
