#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "amp/core/error.hpp"
#include "amp/core/settings_schema.hpp"
#include "amp/nav/sins/clutter_world.hpp"
#include "amp/nav/sins/motor_schemas.hpp"

namespace amp::core {
class Rng;
class StopCondition;
}  // namespace amp::core

namespace amp::nav {

class ParameterPolicy;

// The scale of the clutter worlds against the robot, which the paper's figures lost: the classic
// arena (ClutterWorldSettings's defaults: a 40 m box, circles of 0.5-2 m) with its lengths times
// `factor`, and the step limit. The calibrated scale is the one at which the paper's two baselines
// solve what they solve in its final table (static 14.5%, random 41.5% at 25% clutter), found by
// `amp sins --calibrate` (bench::calibrate_sins_scale; docs/sins.md, "The calibrated scale").
struct SinsScale {
  std::string_view name;
  double factor = 1.0;
  int step_limit = 1000;
  std::string_view what;
};
inline constexpr SinsScale kCalibratedScale{
    "calibrated", 1.67, 298, "a 66.8 m box, circles of 0.835-3.34 m, 298 steps: the paper's baselines' solved shares (the default)"};
inline constexpr SinsScale kClassicScale{
    "classic", 1.0, 1000, "a 40 m box, circles of 0.5-2 m, 1000 steps (AMP's scale before the calibration)"};
inline constexpr SinsScale kSinsScales[] = {kCalibratedScale, kClassicScale};
// The scale named `name`; throws ParameterError listing the names for any other.
const SinsScale& sins_scale(std::string_view name);

// One SINS experiment (Ram & Santamaria 1993, Sec. 3.1): a sequence of clutter worlds driven by a
// holonomic disc under the motor schemas, with the parameters chosen by a ParameterPolicy.
struct SinsSettings {
  int worlds = 200;             // worlds in the sequence
  int step_limit = kCalibratedScale.step_limit;  // steps per world before it counts as unsolved
  int control_interval = 12;    // steps between two parameter choices (the paper's best, Sec. 3.2)
  double goal_tolerance = 0.5;  // m between the robot's centre and the goal that counts as arrived
  double virtual_collision_distance = 0.1;  // m from the rim: nearer is a virtual collision
  int sensors = 16;             // range sensors in the ring, seeing as far as the sphere of influence
  double sensor_noise = 0.02;   // m, Gaussian
  int change_at = 0;            // from this world on the clutter is clutter_after (0: no change)
  double clutter_after = 0.5;
  // The adaptive system's least exploration when stalled (CaseBasedParameters; 0: the paper's).
  double stall_exploration = 0.5;
  SchemaSettings motor{};
  ClutterWorldSettings world = ClutterWorldSettings{}.scaled(kCalibratedScale.factor);

  // The world and the step limit of `scale` (the rest unchanged).
  void set_scale(const SinsScale& scale) {
    const ClutterWorldSettings lengths = ClutterWorldSettings{}.scaled(scale.factor);
    world.width = lengths.width;
    world.height = lengths.height;
    world.min_radius = lengths.min_radius;
    world.max_radius = lengths.max_radius;
    step_limit = scale.step_limit;
  }

  // Every scalar above, and world.clutter as `clutter`, for `amp bench` and the command line.
  static const core::SettingsSchema<SinsSettings>& schema();
  // Throws ParameterError (one line naming the setting) for any value out of range.
  void validate() const;
};

// One world's result: the paper's estimators before averaging.
struct WorldOutcome {
  int index = 0;
  bool solved = false;
  int steps = 0;                 // steps taken (the step limit when unsolved)
  double distance = 0.0;         // m driven
  double optimal = 0.0;          // the world's optimal length (ClutterWorld::optimal_length)
  int virtual_collisions = 0;    // times the robot came nearer than the set distance (each approach once)
  int blocked = 0;               // moves an obstacle cut short (never passed through)
  double min_clearance = 0.0;    // m, the least clearance of the disc over the run (never < 0)
  double time_ms = 0.0;          // measured wall time of the world
  double clutter = 0.0;          // the world's achieved clutter
};

// A world's driven trace, for figures: the position after every step (the start first) and the
// parameters in force during each step.
struct WorldTrace {
  std::vector<Eigen::Vector2d> positions;
  std::vector<SchemaParameters> parameters;
};

// The six estimators of Sec. 3.1 over some worlds. distance_ratio_mean is over the solved worlds
// (0 when none is); the others are over all of them.
struct Estimators {
  int worlds = 0;
  double solved_fraction = 0.0;
  double steps_mean = 0.0;
  double distance_mean = 0.0;
  double distance_ratio_mean = 0.0;  // distance / optimal
  double virtual_collisions_mean = 0.0;
  double time_per_world_ms_mean = 0.0;
};
Estimators estimate(const std::vector<WorldOutcome>& worlds, std::size_t count);
// The cumulative averages after each world (the paper's Figure 5 curves).
std::vector<Estimators> cumulative_estimates(const std::vector<WorldOutcome>& worlds);

// Drives one world: the disc starts at world.start, reads its ring, and moves by the motor schemas'
// velocity every step; every control_interval steps the policy gets the interval's inputs and sets
// the parameters. Ends on arrival (the step's segment passes within goal_tolerance of the goal),
// at step_limit, or when `stop` fires (then unsolved, steps so far). Every draw comes from `rng`.
WorldOutcome run_world(const ClutterWorld& world, int index, ParameterPolicy& policy, const SinsSettings& settings,
                       core::Rng& rng, const core::StopCondition* stop = nullptr, WorldTrace* trace = nullptr);

struct SequenceOutcome {
  std::vector<WorldOutcome> worlds;
  int rejected_worlds = 0;  // drawn and thrown away by the generator
  int cases = 0;            // the policy's cases at the end
  bool stopped = false;     // `stop` fired before the last world
};

// The sequence of `settings.worlds` worlds from ClutterWorldSequence(seed, settings.world), the
// clutter switched at change_at; the robot's draws come from Rng(derive_seed(seed, kRobotStream)),
// so every system meets the same worlds. `on_world` (optional) sees each world's outcome as it ends.
inline constexpr std::uint64_t kRobotStream = 0x51a5'0000'0000'0001ULL;
SequenceOutcome run_sequence(ParameterPolicy& policy, const SinsSettings& settings, std::uint64_t seed,
                             const core::StopCondition* stop = nullptr,
                             const std::function<void(const WorldOutcome&)>& on_world = {});

// The worlds run_sequence meets, drawn at once: world i of ClutterWorldSequence(seed, settings.world),
// the clutter switched at change_at. A clutter no world can be drawn at throws SequenceDrawError
// ("world 3: clutter 0.9: no world with a free path in 100 tries"), which says whether the world
// came after the change, so that a caller can name its own option.
struct SequenceWorlds {
  std::vector<ClutterWorld> worlds;
  int rejected = 0;
};
class SequenceDrawError : public ParameterError {
 public:
  SequenceDrawError(int index, bool after_change, const std::string& detail)
      : ParameterError("world " + std::to_string(index + 1) + ": " + detail), after_change_(after_change) {}
  bool after_change() const { return after_change_; }

 private:
  bool after_change_;
};
SequenceWorlds draw_sequence_worlds(const SinsSettings& settings, std::uint64_t seed);

// What a caller may watch of a sequence: `stop` (optional) ends it early, `on_world` sees each
// world's outcome as it ends, and `last_trace` (optional) receives the last world's driven trace.
struct SequenceHooks {
  const core::StopCondition* stop = nullptr;
  std::function<void(const WorldOutcome&)> on_world;
  WorldTrace* last_trace = nullptr;
};
// run_sequence over worlds already drawn (so that several systems, or several step limits, meet the
// same worlds without drawing them again): the same outcomes as run_sequence(policy, settings, seed)
// when `worlds` is draw_sequence_worlds(settings, seed).
SequenceOutcome run_sequence(ParameterPolicy& policy, const SinsSettings& settings, std::uint64_t seed,
                             const SequenceWorlds& worlds, const SequenceHooks& hooks = {});

}  // namespace amp::nav
