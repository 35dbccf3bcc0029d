#pragma once
// The roadmap planners by name. Each family registers its planners in its own file of this folder
// (catalog/<family>_planners.cpp), reading each planner's parameters from its Settings' schema; a
// new planner is its algorithm's file, a register call here, and one line in builtin_planners().
#include "amp/core/method_catalog.hpp"
#include "amp/core/parameters.hpp"
#include "amp/roadmap/planner.hpp"

namespace amp::roadmap {

// What `amp bench --list` prints about a planner.
using PlannerInfo = core::MethodInfo;

class PlannerRegistry : public core::MethodCatalog<Planner> {
 public:
  PlannerRegistry() : core::MethodCatalog<Planner>("planner") {}
};

// Every planner of the library, built once on first use and immutable afterwards.
const PlannerRegistry& builtin_planners();

// `prm` (prm/prm.hpp), Lazy PRM among its parameters.
void register_prm(PlannerRegistry& registry);
// `gaussian-prm`, `obprm`, `bridge-prm`: PRM with one of samplers/ (catalog/sampler_prms.cpp).
void register_sampler_prms(PlannerRegistry& registry);
// `hybrid-prm` and `uas` (uas/).
void register_uas_planners(PlannerRegistry& registry);
// `prm-c`, `prm-g`, `prm-l` (competence/).
void register_competence_prms(PlannerRegistry& registry);
// `rrt-connect` (trees/rrt_connect.hpp).
void register_rrt_connect(PlannerRegistry& registry);
// `grid-dp` (grid/grid_dp.hpp).
void register_grid_dp(PlannerRegistry& registry);

}  // namespace amp::roadmap
