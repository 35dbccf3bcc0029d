#pragma once
#include "amp/core/rng.hpp"
#include "amp/core/state.hpp"

namespace amp::roadmap {

// Draws free configurations. Implementations check validity through their ValidityChecker, so every
// CD call a sample costs is counted. Implementations: UniformSampler (later Gaussian, OBPRM, bridge).
// A sampler holds per-thread scratch; use one per thread.
class Sampler {
 public:
  virtual ~Sampler() = default;
  // A free, in-bounds state into `out`, or false after the sampler's bounded number of attempts.
  virtual bool sample(core::Rng& rng, State& out) = 0;
};

}  // namespace amp::roadmap
