#include "amp/nav/sins/sins_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <string>

#include "amp/core/error.hpp"
#include "amp/core/rng.hpp"
#include "amp/core/stop_condition.hpp"
#include "amp/nav/holonomic_disc.hpp"
#include "amp/nav/polygon_nav_world.hpp"
#include "amp/nav/simulator.hpp"
#include "amp/nav/sins/environment_trends.hpp"
#include "amp/nav/sins/parameter_policy.hpp"
#include "amp/world/polygon_geometry.hpp"

namespace amp::nav {

const core::SettingsSchema<SinsSettings>& SinsSettings::schema() {
  using S = SinsSettings;
  static const core::SettingsSchema<S> schema(
      "sins",
      {core::integer_field<S>("worlds", &S::worlds, 1, 1e6, "worlds in the sequence"),
       core::integer_field<S>("step_limit", &S::step_limit, 1, 1e7, "steps per world before it counts as unsolved"),
       core::integer_field<S>("control_interval", &S::control_interval, 1, 1e6,
                              "steps between two choices of the schema parameters"),
       core::real_field<S>("clutter", [](S& s) -> double& { return s.world.clutter; }, 0, 1,
                           "fraction of the box covered by circles, in (0, 1)"),
       core::integer_field<S>("change_at", &S::change_at, 0, 1e6,
                              "from this world on the clutter is clutter_after (0: no change)"),
       core::real_field<S>("clutter_after", &S::clutter_after, 0, 1, "the clutter from world change_at on, in (0, 1)"),
       core::real_field<S>("stall_exploration", &S::stall_exploration, 0, 1,
                           "the adaptive system's least exploration spread when it makes no progress (0: the paper's rule)"),
       core::real_field<S>("goal_tolerance", &S::goal_tolerance, 0, 1e3, "m from the goal that counts as arrived"),
       core::real_field<S>("virtual_collision_distance", &S::virtual_collision_distance, 0, 1e3,
                           "m from the rim: nearer to an obstacle is a virtual collision"),
       core::integer_field<S>("sensors", &S::sensors, 1, 1024, "range sensors in the ring"),
       core::real_field<S>("sensor_noise", &S::sensor_noise, 0, 1e3, "m, standard deviation of each reading"),
       core::real_field<S>("sphere_of_influence", [](S& s) -> double& { return s.motor.sphere_of_influence; }, 0, 1e3,
                           "m beyond the rim within which obstacles repel (and the sensors' range)"),
       core::real_field<S>("max_speed", [](S& s) -> double& { return s.motor.max_speed; }, 0, 1e3,
                           "m per step the robot moves at most"),
       core::real_field<S>("min_radius", [](S& s) -> double& { return s.world.min_radius; }, 0, 1e4,
                           "m, the smallest circle's radius (radii are uniform in [min_radius, max_radius])"),
       core::real_field<S>("max_radius", [](S& s) -> double& { return s.world.max_radius; }, 0, 1e4,
                           "m, the largest circle's radius")});
  return schema;
}

void SinsSettings::validate() const {
  schema().validate(*this);
  motor.validate();
  world.validate();
  auto open_unit = [](double v, const char* name) {
    if (!(v > 0.0 && v < 1.0)) {
      throw ParameterError(std::string("sins: parameter '") + name + "': " + std::to_string(v) + " is outside (0, 1)");
    }
  };
  open_unit(world.clutter, "clutter");
  if (change_at > 0) open_unit(clutter_after, "clutter_after");
  if (!(goal_tolerance > 0.0)) throw ParameterError("sins: parameter 'goal_tolerance' must be > 0");
  if (!(motor.max_speed > 0.0)) throw ParameterError("sins: parameter 'max_speed' must be > 0");
}

Estimators estimate(const std::vector<WorldOutcome>& worlds, std::size_t count) {
  Estimators e;
  count = std::min(count, worlds.size());
  e.worlds = static_cast<int>(count);
  if (count == 0) return e;
  int solved = 0;
  double ratio = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    const WorldOutcome& w = worlds[i];
    solved += w.solved ? 1 : 0;
    if (w.solved) ratio += w.distance / w.optimal;
    e.steps_mean += w.steps;
    e.distance_mean += w.distance;
    e.virtual_collisions_mean += w.virtual_collisions;
    e.time_per_world_ms_mean += w.time_ms;
  }
  const double n = static_cast<double>(count);
  e.solved_fraction = solved / n;
  e.distance_ratio_mean = solved > 0 ? ratio / solved : 0.0;
  e.steps_mean /= n;
  e.distance_mean /= n;
  e.virtual_collisions_mean /= n;
  e.time_per_world_ms_mean /= n;
  return e;
}

std::vector<Estimators> cumulative_estimates(const std::vector<WorldOutcome>& worlds) {
  std::vector<Estimators> out;
  out.reserve(worlds.size());
  for (std::size_t i = 1; i <= worlds.size(); ++i) out.push_back(estimate(worlds, i));
  return out;
}

namespace {

}  // namespace

WorldOutcome run_world(const ClutterWorld& world, int index, ParameterPolicy& policy, const SinsSettings& settings,
                       core::Rng& rng, const core::StopCondition* stop, WorldTrace* trace) {
  const auto started = std::chrono::steady_clock::now();
  const double radius = settings.world.robot_radius;
  SimulatorSettings sim_settings;
  sim_settings.time_step = 1.0;  // one schema step; the disc's speed is then in m per step
  sim_settings.sensors.count = settings.sensors;
  sim_settings.sensors.max_range = settings.motor.sphere_of_influence;
  sim_settings.sensors.noise_stddev = settings.sensor_noise;
  auto robot = std::make_shared<const HolonomicDisc>(HolonomicDiscSettings{radius, settings.motor.max_speed});
  auto timeline = std::make_shared<const WorldTimeline>(world.world, std::vector<WorldEvent>{});
  RobotState start;
  start.position = world.start;
  Simulator sim(timeline, robot, start, sim_settings);
  MotorSchemas schemas(settings.motor);
  EnvironmentTrends trends(settings.motor.sphere_of_influence, settings.motor.max_speed);
  trends.reset(world.start, world.goal);

  std::vector<Eigen::Vector2d> directions(static_cast<std::size_t>(settings.sensors));
  for (int i = 0; i < settings.sensors; ++i) directions[static_cast<std::size_t>(i)] = sim.sensors().direction(i, 0.0);
  std::vector<double> first(static_cast<std::size_t>(settings.sensors));
  sim.sensors().read(*world.world, sim.state(), radius, rng, first);

  WorldOutcome out;
  out.index = index;
  out.optimal = world.optimal_length;
  out.clutter = world.clutter;
  out.min_clearance = world.world->clearance(world.start, radius);
  bool near = out.min_clearance < settings.virtual_collision_distance;
  out.virtual_collisions = near ? 1 : 0;
  SchemaParameters params = policy.begin_world(rng);
  if (trace != nullptr) {
    trace->positions.assign(1, world.start);
    trace->parameters.clear();
  }
  bool arrived = (world.start - world.goal).norm() <= settings.goal_tolerance;
  while (!arrived && out.steps < settings.step_limit) {
    if (stop != nullptr && (out.steps & 63) == 0 && stop->time_up()) break;
    const Eigen::Vector2d from = sim.state().position;
    const std::span<const double> readings = out.steps == 0 ? std::span<const double>(first) : sim.ranges();
    const Eigen::Vector2d v = schemas.velocity(from, world.goal, readings, directions, params, rng);
    const StepResult r = sim.step(v, rng);
    const Eigen::Vector2d& to = sim.state().position;
    ++out.steps;
    out.distance += r.travelled;
    out.blocked += r.blocked ? 1 : 0;
    const double clearance = world.world->clearance(to, radius);
    out.min_clearance = std::min(out.min_clearance, clearance);
    const bool now_near = clearance < settings.virtual_collision_distance;
    if (now_near && !near) ++out.virtual_collisions;
    near = now_near;
    trends.step(sim.ranges(), to);
    if (trace != nullptr) {
      trace->positions.push_back(to);
      trace->parameters.push_back(params);
    }
    arrived = std::sqrt(world::point_segment_distance_sq(world.goal, from, to)) <= settings.goal_tolerance;
    if (!arrived && out.steps % settings.control_interval == 0) params = policy.end_interval(trends.close_interval(), rng);
  }
  out.solved = arrived;
  if (arrived || out.steps >= settings.step_limit) {
    policy.end_world(arrived, static_cast<double>(out.steps) / settings.step_limit);
  }
  out.min_clearance = std::max(0.0, out.min_clearance);
  out.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
  return out;
}

const SinsScale& sins_scale(std::string_view name) {
  std::string names;
  for (const SinsScale& s : kSinsScales) {
    if (s.name == name) return s;
    names += (names.empty() ? "" : ", ") + std::string(s.name);
  }
  throw ParameterError("sins: unknown scale '" + std::string(name) + "' (valid: " + names + ")");
}

namespace {

// The one sequence loop: world i from `world_at(i)` (drawn on the way, or already drawn), driven by
// `policy` with the robot's draws from Rng(derive_seed(seed, kRobotStream)).
SequenceOutcome drive_sequence(ParameterPolicy& policy, const SinsSettings& settings, std::uint64_t seed, int count,
                               const std::function<const ClutterWorld&(int)>& world_at, const SequenceHooks& hooks) {
  core::Rng rng(core::derive_seed(seed, kRobotStream));
  SequenceOutcome out;
  out.worlds.reserve(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    if (hooks.stop != nullptr && hooks.stop->time_up()) {
      out.stopped = true;
      break;
    }
    WorldTrace* trace = i + 1 == count ? hooks.last_trace : nullptr;
    out.worlds.push_back(run_world(world_at(i), i, policy, settings, rng, hooks.stop, trace));
    if (hooks.on_world) hooks.on_world(out.worlds.back());
  }
  out.cases = policy.cases();
  return out;
}

}  // namespace

SequenceWorlds draw_sequence_worlds(const SinsSettings& settings, std::uint64_t seed) {
  settings.validate();
  ClutterWorldSequence sequence(seed, settings.world);
  SequenceWorlds out;
  out.worlds.reserve(static_cast<std::size_t>(settings.worlds));
  for (int i = 0; i < settings.worlds; ++i) {
    const bool after_change = settings.change_at > 0 && i >= settings.change_at;
    try {
      if (settings.change_at > 0 && i == settings.change_at) sequence.set_clutter(settings.clutter_after);
      out.worlds.push_back(sequence.next());
    } catch (const ParameterError& e) {
      throw SequenceDrawError(i, after_change, e.what());
    }
  }
  out.rejected = sequence.rejected_total();
  return out;
}

SequenceOutcome run_sequence(ParameterPolicy& policy, const SinsSettings& settings, std::uint64_t seed,
                             const SequenceWorlds& worlds, const SequenceHooks& hooks) {
  settings.validate();
  const auto world_at = [&worlds](int i) -> const ClutterWorld& { return worlds.worlds[static_cast<std::size_t>(i)]; };
  SequenceOutcome out =
      drive_sequence(policy, settings, seed, static_cast<int>(worlds.worlds.size()), world_at, hooks);
  out.rejected_worlds = worlds.rejected;
  return out;
}

SequenceOutcome run_sequence(ParameterPolicy& policy, const SinsSettings& settings, std::uint64_t seed,
                             const core::StopCondition* stop, const std::function<void(const WorldOutcome&)>& on_world) {
  settings.validate();
  ClutterWorldSequence sequence(seed, settings.world);
  ClutterWorld current;
  // Drawn only when reached, so a stopped run draws no world it does not drive.
  const auto world_at = [&](int i) -> const ClutterWorld& {
    if (settings.change_at > 0 && i == settings.change_at) sequence.set_clutter(settings.clutter_after);
    current = sequence.next();
    return current;
  };
  SequenceOutcome out = drive_sequence(policy, settings, seed, settings.worlds, world_at, {stop, on_world, nullptr});
  out.rejected_worlds = sequence.rejected_total();
  return out;
}

}  // namespace amp::nav
