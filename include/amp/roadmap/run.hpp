#pragma once
#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "amp/core/run_record.hpp"
#include "amp/core/parameters.hpp"
#include "amp/roadmap/catalog/planner_registry.hpp"
#include "amp/roadmap/roadmap.hpp"
#include "amp/world/problem.hpp"

namespace amp::roadmap {

struct RunOutcome {
  core::RunRecord record;
  std::vector<State> path;
  std::shared_ptr<const Roadmap> roadmap;  // may be null
};

// One run of a planner on a problem, as `amp plan` and `amp bench` do it: fresh counters and checker,
// Rng(seed), a StopCondition(time_limit_s, node_limit), the plan timed, the record filled (path
// length, and path clearance = the smallest clearance over the path's states sampled at the space's
// resolution, measured with a separate checker so that it costs the run nothing).
// `cancel`, when set, stops the planner as a time limit would (Ctrl-C in `amp bench`).
// A planner that throws gives status kError with its message; an unknown planner, a bad parameter
// (ParameterError) or a bad seed (InvalidSeedError) is the user's error and is rethrown.
RunOutcome execute_run(const world::Problem& problem, const std::string& planner, const core::ParamMap& params,
                       std::uint64_t seed, double time_limit_s, std::size_t node_limit,
                       const PlannerRegistry& registry = builtin_planners(),
                       const std::atomic<bool>* cancel = nullptr);

// `params` plus the problem's parameter defaults (`defaults.params`) that the planner declares and
// `params` does not set: run settings override problem settings, which override planner defaults.
core::ParamMap with_problem_params(const world::Problem& problem, const PlannerInfo& planner, core::ParamMap params);

// Smallest clearance along `path`, sampling each segment at the space's resolution; 0 for an empty path.
double path_clearance(const core::Space& space, const world::ValidityChecker& checker, const std::vector<State>& path);

}  // namespace amp::roadmap
