#pragma once
#include <vector>

#include "amp/core/state.hpp"
#include "amp/core/stop_condition.hpp"
#include "amp/nav/policy/policy_value.hpp"

namespace amp::nav {

struct PolicySearchSettings {
  double obstacle_weight = 1.0;  // weight of eq. 11's push from the nearest obstacle point
  double min_move = 1e-3;        // m: the line search halves the step down to this
  int max_sweeps = 100;          // sweeps over the waypoints per search (Table 1, step 3d)
  int max_insertions = 30;       // waypoints inserted at most (Table 1, step 5)
  double tolerance = 1e-6;       // a sweep that gains less has converged
  double v_factor = 1.25;        // the speed line search tries v * f and v / f
  double v_min = 0.05;           // m/s, the slowest waypoint speed
  double v_max = 0.26;           // m/s, the fastest
  // Throws ParameterError naming the setting.
  void validate() const;
};

// The waypoints after each phase of Table 1 (the paper's Figure 3 b-d) and their values.
struct PolicySearchResult {
  std::vector<State> projected, searched, final;
  double value_projected = 0.0, value_searched = 0.0, value_final = 0.0;
  int sweeps = 0;      // over every search
  int insertions = 0;  // waypoints inserted and kept
  bool stopped = false;  // `stop` fired: `final` is the last policy kept (every move in it was proved free)
};

// Policy search of "Policy search seeded by a value function" (Table 1, steps 3-5). For each inner
// waypoint w_j in turn: the ascent direction of eq. 11, (w_j-1 - w_j) + (w_j+1 - w_j) -
// k (zeta(w_j) - w_j) with zeta the nearest obstacle point, and a line search that halves the step
// until the value of the two segments at w_j increases (the move is kept only if both segments stay
// free for the disc, proved by conservative advancement); then the speed, tried times and divided by
// v_factor. Sweeps repeat until one gains less than `tolerance`. Then a waypoint is inserted at the
// lowest immediate reward between two waypoints where it is below the reward at both (eq. 10), the
// search runs again, and insertion stops when it no longer raises the value. Headings follow the
// segments (each waypoint faces along the one it begins); turn rates stay 0. The start and the goal
// never move. Deterministic. `stop` (optional) is read before each waypoint's step, which evaluates
// the value and proves segments free several times: the search ends there, keeping what it has.
PolicySearchResult search_policy(std::vector<State> initial, const PolicyValue& value, const PolicySearchSettings& settings = {},
                                 const core::StopCondition* stop = nullptr);

// Each waypoint faces along the segment it begins (the last along the one it ends); turn rates 0.
void face_along(std::vector<State>& w);

// Whether the disc of radius r is free all along a -> b (conservative advancement on the world's
// exact clearance; touching counts as blocked).
bool segment_free(const NavWorld& world, const Eigen::Vector2d& a, const Eigen::Vector2d& b, double r);

}  // namespace amp::nav
