#include "amp/roadmap/uas/hybrid_observer.hpp"

namespace amp::roadmap {

void HybridObserver::inserted(const Roadmap& roadmap, const Insertion& insertion) {
  classes_.inserted(roadmap, insertion);
  sampler_->observe(roadmap, insertion);
  if (!insertion.seed) sampler_->reward_last(insertion);
}

void HybridObserver::report(std::map<std::string, double>& extra) const {
  classes_.report(extra);
  sampler_->report(extra);
}

}  // namespace amp::roadmap
