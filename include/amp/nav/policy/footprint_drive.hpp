#pragma once
#include <cstddef>
#include <vector>

#include "amp/core/state.hpp"
#include "amp/nav/policy/policy_value.hpp"

namespace amp::nav {

// Whether a waypoint policy can be driven by the value's footprint, and the repairs that make it so
// for a footprint that is not a disc. A policy is driven segment by segment, the footprint facing
// along each, turning in place at the inner waypoints (the waypoint controller switches within the
// goal tolerance for such a footprint). The robot starts facing the goal.

// Segment k (w_k -> w_k+1) driven at its heading: every disc of the footprint along its own parallel
// segment, by conservative advancement.
bool segment_drivable(const PolicyValue& value, const std::vector<State>& w, std::size_t k);
// The turn in place at waypoint k, from segment k-1's heading to segment k's; at the start, from
// facing the goal, as the robot starts. True at the goal and for a disc.
bool turn_drivable(const PolicyValue& value, const std::vector<State>& w, std::size_t k);
// Whether the value's footprint can drive the whole policy: each segment at its heading and each
// turn in place at an inner waypoint.
bool policy_free(const PolicyValue& value, const std::vector<State>& w);

// For a footprint that is not a disc, on a grid path's waypoints: each inner waypoint whose segments
// or turn the footprint cannot drive is dropped if the policy is drivable there without it (a jog of
// the grid path), or else moves, by `step` at a time up to the footprint's length + width, further
// along its incoming segment (to turn once out of a door) or back along its outgoing one (to line up
// before entering it), to the first place where its segments and turns are drivable. Headings then
// follow the segments. Returns whether the whole policy is then drivable.
bool make_drivable(const PolicyValue& value, std::vector<State>& w, double step);

// For a footprint that is not a disc, on a drivable policy: where a segment passes closer than the
// value's safety range at rest (a door, slanted), a crossing of the same place at another heading
// and offset that leaves the footprint more room (by at least kMinCrossingGain) replaces it, as two
// waypoints inserted on either side: the body is squared up before the passage and turns only once
// out of it. A noisy robot holds a square crossing of a 60 cm door with a 54 cm body; a slanted one
// with millimetres to spare, it does not. Candidates are headings within 60 degrees of the segment's,
// by 1 degree, and offsets across it by `step` / 4 up to `step`; the one with the most room along
// the passage wins, and it is kept only if every segment and turn it changes stays drivable.
// Deterministic; returns how many crossings were replaced.
inline constexpr double kMinCrossingGain = 0.01;  // m: less is not worth two more stops
int square_crossings(const PolicyValue& value, std::vector<State>& w, double step);

}  // namespace amp::nav
