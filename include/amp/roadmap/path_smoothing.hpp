#pragma once
#include <vector>

#include "amp/core/rng.hpp"
#include "amp/core/space.hpp"
#include "amp/roadmap/local_planner.hpp"

namespace amp::roadmap {

// Sum of space distances between consecutive states (0 for fewer than two states).
double path_length(const core::Space& space, const std::vector<State>& path);

// Random shortcutting: `attempts` times, pick two path states at least two apart and, when the
// local planner joins them, drop the states between. All randomness from `rng`, so a run's seed
// fixes the result. Returns the number of shortcuts taken.
int shortcut_path(LocalPlanner& local_planner, core::Rng& rng, int attempts, std::vector<State>& path);

}  // namespace amp::roadmap
