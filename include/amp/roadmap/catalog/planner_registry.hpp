#pragma once
// The roadmap planners by name. Each family registers its planners in its own file of this folder
// (catalog/<family>_planners.cpp), reading each planner's parameters from its Settings' schema; a
// new planner is its algorithm's file, a register call here, and one line in builtin_planners().
#include <cstddef>

#include "amp/core/method_catalog.hpp"
#include "amp/core/parameters.hpp"
#include "amp/roadmap/planner.hpp"

namespace amp::roadmap {

// A roadmap's node limit when no run, problem or experiment sets one.
inline constexpr std::size_t kDefaultNodeLimit = 20000;

// What `amp bench --list` prints about a planner.
struct PlannerInfo : core::MethodInfo {
  // The node limit a run of this planner gets when none is given (resolve_node_limit, run.hpp): a
  // roadmap grows until stopped, so it needs one; world::kNoNodeLimit for a planner whose input
  // bounds its work already (grid-dp settles each of the map's cells at most once).
  std::size_t default_node_limit = kDefaultNodeLimit;
};

class PlannerRegistry : public core::MethodCatalog<Planner, PlannerInfo> {
 public:
  PlannerRegistry() : core::MethodCatalog<Planner, PlannerInfo>("planner") {}
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
