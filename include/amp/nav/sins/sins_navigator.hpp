#pragma once
#include <string>

#include "amp/learn/case_library.hpp"
#include "amp/learn/splitting_cases.hpp"
#include "amp/nav/navigator.hpp"
#include "amp/nav/sins/motor_schemas.hpp"
#include "amp/nav/sins/sins_run.hpp"

namespace amp::nav {

// SINS's three systems (Ram & Santamaria 1993, Sec. 3) as `amp bench` navigation methods `static`,
// `random` and `sins`, and AMP's `sins-plus` (SplittingCaseParameters). One run is one whole
// sequence of `settings.worlds` clutter worlds (run_sequence) with one ParameterPolicy that lives through it, so what SINS learns carries from
// world to world as in the paper. The task gives the arena only: the problem's bounds become the box
// (they must start at (0, 0)) and its disc robot's radius the robot's; the problem must have no
// obstacles and no events, since the worlds are drawn by the method. The run's start and goal are
// not used (every world draws its own).
//
// The sequence's seed is the first 64-bit draw from the run's Rng (Navigator::run gets an Rng, not a
// seed; execute_navigation builds it as Rng(run seed)), so the sequence, and the record, depend on
// the run's seed alone. Record: status solved when every world was run (whatever their outcomes),
// timeout when the stop fired first; path_length the distance driven over all worlds; extras the
// estimators of Sec. 3.1 over the worlds run (solved_fraction, steps_mean, distance_mean,
// distance_ratio_mean, virtual_collisions_mean), `worlds` run, `cases` at the end and
// `rejected_worlds`. No measured time enters the record: the time per world is wall_time_s / worlds.
// No trace (the worlds are not the problem's).
class SinsNavigator final : public Navigator {
 public:
  // `system`: "static", "random", "adaptive" or "sins-plus" (`plus` its settings). Throws
  // ParameterError for bad settings, parameters or cases (the box is checked in run(), against the task).
  SinsNavigator(std::string system, SinsSettings settings, SchemaParameters initial, learn::CaseSettings cases,
                learn::SplittingCaseSettings plus = {});
  NavigationOutcome run(const NavTask& task, const core::StopCondition& stop, core::Rng& rng) override;

  // The settings for the task's arena: settings.world's box and robot radius from the task. Throws
  // ParameterError naming the task's problem when it is not an empty box at the origin, or too small.
  static SinsSettings arena_settings(const SinsSettings& settings, const NavTask& task);

 private:
  std::string system_;
  SinsSettings settings_;
  SchemaParameters initial_;
  learn::CaseSettings cases_;
  learn::SplittingCaseSettings plus_;
};

}  // namespace amp::nav
