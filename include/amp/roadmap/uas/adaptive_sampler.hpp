#pragma once
#include <map>
#include <string>

#include "amp/roadmap/prm/insertion_observer.hpp"
#include "amp/roadmap/roadmap.hpp"
#include "amp/roadmap/samplers/sampler.hpp"

namespace amp::roadmap {

// A sampler that learns from what its last sample did once PRM inserted it (Hybrid PRM; UAS, which
// routes the reward to the region that drew the sample).
class AdaptiveSampler : public Sampler {
 public:
  // The last successful sample is now inserted; a call with nothing pending does nothing.
  virtual void reward_last(const Insertion& insertion) = 0;
  // Its per-run figures (PlanResult::extra).
  virtual void report(std::map<std::string, double>& extra) const = 0;
  // Every vertex the run inserts, seeds included, before reward_last: samplers that grow from the
  // roadmap (the expansion step) learn their candidates here.
  virtual void observe(const Roadmap& roadmap, const Insertion& insertion) = 0;
};

}  // namespace amp::roadmap
