#include "amp/roadmap/samplers/random_offset.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "amp/core/error.hpp"
#include "amp/world/planning_features.hpp"

namespace amp::roadmap {

void validate_offset_settings(std::string_view sampler, double d, int max_attempts) {
  if (!(d > 0.0) || !std::isfinite(d)) {
    throw ParameterError(std::string(sampler) + " sampler: d must be positive and finite, got " + std::to_string(d));
  }
  if (max_attempts < 1) {
    throw ParameterError(std::string(sampler) + " sampler: max_attempts must be >= 1, got " + std::to_string(max_attempts));
  }
}

SamplerDistance sampler_distance(const world::PlanningFeatures& features, const core::Space& space, double scale) {
  const double r = features.robot_min_diameter();
  if (r > 0.0 && std::isfinite(r)) return {scale * r, false};
  return {scale * kFallbackExtentFraction * space.maximum_extent(), true};
}

void random_offset(const core::Space& space, core::Rng& rng, const State& from, double delta, State& out) {
  State target;
  space.sample_uniform(rng, target);
  const double dist = space.distance(from, target);
  if (!(dist > 0.0)) {  // drew `from` itself: no direction, stay put (the caller's pair is then equal)
    out = from;
    return;
  }
  space.interpolate(from, target, std::min(1.0, delta / dist), out);
}

}  // namespace amp::roadmap
