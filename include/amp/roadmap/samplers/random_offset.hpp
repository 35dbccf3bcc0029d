#pragma once
#include <string_view>

#include "amp/core/rng.hpp"
#include "amp/core/space.hpp"
#include "amp/core/state.hpp"

namespace amp::world {
class PlanningFeatures;
}

namespace amp::roadmap {

// The distance of the obstacle-based samplers (Gaussian d, bridge length): scale * r, r = the robot's
// smallest diameter (UAS uses d = r and d = 2r). A point robot has r = 0; then 1% of the space's
// extent stands in for r and `fallback` says so (it is recorded as an extra of the run).
struct SamplerDistance {
  double d = 0.0;
  bool fallback = false;
};
inline constexpr double kFallbackExtentFraction = 0.01;
SamplerDistance sampler_distance(const world::PlanningFeatures& features, const core::Space& space, double scale);

// The settings every offset-drawing sampler shares (Gaussian, bridge, expansion): throws
// ParameterError naming `sampler` unless d is positive and finite and max_attempts >= 1.
void validate_offset_settings(std::string_view sampler, double d, int max_attempts);

// `out` = `from` moved a distance `delta` >= 0 (the space's metric) along a random direction: towards
// a uniform state u of the space, along the space's geodesic (so SE2/SE3/linkages are handled), but
// never past u. Stays inside the space's bounds (a geodesic between two in-bounds states does).
void random_offset(const core::Space& space, core::Rng& rng, const State& from, double delta, State& out);

}  // namespace amp::roadmap
