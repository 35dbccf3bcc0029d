#include "amp/roadmap/catalog/planner_registry.hpp"

namespace amp::roadmap {

const PlannerRegistry& builtin_planners() {
  // A function-local constant, not mutable global state: built once (thread-safe), never changed.
  static const PlannerRegistry registry = [] {
    PlannerRegistry r;
    register_prm(r);
    register_sampler_prms(r);
    register_uas_planners(r);
    register_competence_prms(r);
    register_rrt_connect(r);
    register_grid_dp(r);
    return r;
  }();
  return registry;
}

}  // namespace amp::roadmap
