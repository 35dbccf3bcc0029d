#pragma once
#include <map>
#include <string>

#include "amp/roadmap/prm/insertion_observer.hpp"
#include "amp/roadmap/roadmap.hpp"

namespace amp::roadmap {

// The learning half of an adaptive sampler: what its last sample did once PRM inserted it (Hybrid
// PRM; UAS, which routes the reward to the region that drew the sample). A role beside Sampler, not
// below it: HybridSampler and RegionalSampler are both, and HybridObserver holds only this half.
class SampleLearner {
 public:
  virtual ~SampleLearner() = default;
  // The last successful sample is now inserted; a call with nothing pending does nothing.
  virtual void reward_last(const Insertion& insertion) = 0;
  // Its per-run figures (PlanResult::extra).
  virtual void report(std::map<std::string, double>& extra) const = 0;
  // Every vertex the run inserts, seeds included, before reward_last: samplers that grow from the
  // roadmap (the expansion step) learn their candidates here.
  virtual void observe(const Roadmap& roadmap, const Insertion& insertion) = 0;
};

}  // namespace amp::roadmap
