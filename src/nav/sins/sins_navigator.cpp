#include "amp/nav/sins/sins_navigator.hpp"

#include <memory>
#include <utility>
#include <vector>

#include "amp/core/error.hpp"
#include "amp/core/rng.hpp"
#include "amp/core/stop_condition.hpp"
#include "amp/nav/navigator_catalog.hpp"
#include "amp/nav/polygon_nav_world.hpp"
#include "amp/nav/sins/parameter_policy.hpp"
#include "amp/nav/world_timeline.hpp"

namespace amp::nav {

namespace {

// How far the bounds' lower corner may lie from (0, 0) and still count as the origin.
constexpr double kOriginTolerance = 1e-9;

}  // namespace

SinsNavigator::SinsNavigator(std::string system, SinsSettings settings, SchemaParameters initial,
                             learn::CaseSettings cases, learn::SplittingCaseSettings plus)
    : system_(std::move(system)), settings_(settings), initial_(initial), cases_(cases), plus_(plus) {
  settings_.validate();
  initial_.validate();
  cases_.validate();
  plus_.validate();
  // An unknown system fails here, not in a run.
  make_parameter_policy(system_, cases_, initial_, settings_.stall_exploration, plus_);
}

SinsSettings SinsNavigator::arena_settings(const SinsSettings& settings, const NavTask& task) {
  const std::string where = "problem '" + task.name + "'";
  const auto fail = [&](const std::string& what) { throw ParameterError(where + ": " + what); };
  if (!task.timeline) fail("no world");
  const PolygonNavWorld* polygons = task.timeline->base()->as_polygons();
  if (polygons == nullptr || !polygons->world().obstacles().empty() || !task.timeline->events().empty()) {
    fail("sins methods draw their own worlds; the problem must be an empty box");
  }
  const Eigen::AlignedBox2d& box = polygons->bounds();
  if (box.min().cwiseAbs().maxCoeff() > kOriginTolerance) {
    fail("sins methods need bounds starting at [0, 0] (the clutter worlds' box is [0, width] x [0, height])");
  }
  SinsSettings s = settings;
  s.world.width = box.max().x();
  s.world.height = box.max().y();
  s.world.robot_radius = task.robot_radius;
  try {
    s.validate();
  } catch (const ParameterError& e) {
    fail(e.what());  // a box too small for the robot's start and goal discs
  }
  return s;
}

NavigationOutcome SinsNavigator::run(const NavTask& task, const core::StopCondition& stop, core::Rng& rng) {
  const SinsSettings settings = arena_settings(settings_, task);
  // The run's one draw: the sequence's seed (worlds and robot), so everything depends on the run's seed.
  const std::uint64_t seed = rng.next_u64();
  std::unique_ptr<ParameterPolicy> policy =
      make_parameter_policy(system_, cases_, initial_, settings_.stall_exploration, plus_);
  const SequenceOutcome seq = run_sequence(*policy, settings, seed, &stop);

  NavigationOutcome out;
  core::RunRecord& r = out.record;
  const bool complete = !seq.stopped && !stop.fired() && static_cast<int>(seq.worlds.size()) == settings.worlds;
  r.status = complete ? core::PlanStatus::kSolved : core::PlanStatus::kTimeout;
  const Estimators e = estimate(seq.worlds, seq.worlds.size());
  for (const WorldOutcome& w : seq.worlds) r.path_length += w.distance;
  // Sec. 3.1's estimators but the time per world, which is measured (wall_time_s / worlds): the
  // record depends on the seed alone.
  r.extra["worlds"] = static_cast<double>(e.worlds);
  r.extra["solved_fraction"] = e.solved_fraction;
  r.extra["steps_mean"] = e.steps_mean;
  r.extra["distance_mean"] = e.distance_mean;
  r.extra["distance_ratio_mean"] = e.distance_ratio_mean;
  r.extra["virtual_collisions_mean"] = e.virtual_collisions_mean;
  r.extra["cases"] = static_cast<double>(seq.cases);
  r.extra["rejected_worlds"] = static_cast<double>(seq.rejected_worlds);
  return out;
}

void register_sins(NavigatorRegistry& registry) {
  struct System {
    const char* name;
    const char* policy;  // make_parameter_policy's name
    const char* what;
    bool initial;        // reads the schema parameters (the random system draws its own)
    bool cases;          // reads the case settings
    bool plus;           // reads sins-plus's settings
  };
  static constexpr System kSystems[] = {
      {"static", "static",
       "the static system: fixed motor-schema parameters (obstacle_gain, goal_gain, noise_gain, noise_persistence)",
       true, false, false},
      {"random", "random", "the random system: every schema parameter drawn anew after each control interval", false,
       false, false},
      {"sins", "adaptive",
       "SINS: case-based reasoning and reinforcement learning choose the schema parameters every control interval, "
       "the cases carried from world to world",
       true, true, false},
      {"sins-plus", "sins-plus",
       "sins-plus (AMP, beyond the paper; docs/sins.md): cases of situations whose outputs learn from the progress "
       "over a horizon of control intervals, a case split when its situations want opposite outputs; starts from "
       "the schema parameters given",
       true, false, true},
  };
  for (const System& sys : kSystems) {
    std::vector<core::ParamSpec> specs = SinsSettings::schema().specs();
    if (sys.initial) {
      for (const core::ParamSpec& s : SchemaParameters::schema().specs()) specs.push_back(s);
    }
    if (sys.cases) {
      for (const core::ParamSpec& s : learn::CaseSettings::schema().specs()) specs.push_back(s);
    }
    if (sys.plus) {
      for (const core::ParamSpec& s : learn::SplittingCaseSettings::schema().specs()) specs.push_back(s);
    }
    registry.add({sys.name,
                  std::string(sys.what) +
                      " (Ram & Santamaria 1993); a run drives a disc through a sequence of clutter worlds drawn in the "
                      "problem's empty box",
                  specs},
                 [sys](const core::Params& p) -> std::unique_ptr<Navigator> {
                   return std::make_unique<SinsNavigator>(
                       sys.policy, SinsSettings::schema().read(p),
                       sys.initial ? SchemaParameters::schema().read(p) : SchemaParameters::middle(),
                       sys.cases ? learn::CaseSettings::schema().read(p) : learn::CaseSettings{},
                       sys.plus ? learn::SplittingCaseSettings::schema().read(p) : learn::SplittingCaseSettings{});
                 });
  }
}

}  // namespace amp::nav
