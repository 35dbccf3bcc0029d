#pragma once
#include <vector>

#include "amp/core/rng.hpp"
#include "amp/core/space.hpp"
#include "amp/core/stop_condition.hpp"
#include "amp/roadmap/local_planners/local_planner.hpp"

namespace amp::roadmap {

// Sum of space distances between consecutive states (0 for fewer than two states).
double path_length(const core::Space& space, const std::vector<State>& path);

// Random shortcutting: `attempts` times, pick two path states at least two apart and, when the
// local planner joins them, drop the states between. All randomness from `rng`, so a run's seed
// fixes the result. Returns the number of shortcuts taken. `stop`, when given, ends the attempts
// once it fires (time or cancel, read before each attempt): smoothing runs after the planner found
// its path and must not carry the run past its limit; the path is valid after any attempt.
int shortcut_path(LocalPlanner& local_planner, core::Rng& rng, int attempts, std::vector<State>& path,
                  const core::StopCondition* stop = nullptr);

}  // namespace amp::roadmap
