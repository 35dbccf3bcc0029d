#pragma once
#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
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
// Rng(seed), a StopCondition(time_limit_s, resolve_node_limit(node_limit, ...)), the plan timed,
// the record filled (path length, and path clearance = the smallest clearance over the path's
// states sampled at the space's resolution, measured with a separate checker so that it costs the
// run nothing).
// `cancel`, when set, stops the planner as a time limit would (Ctrl-C in `amp bench`).
// A planner that throws gives status kError with its message; an unknown planner, a bad parameter
// (ParameterError) or a bad seed (InvalidSeedError) is the user's error and is rethrown.
// `node_limit` is the run's own (`--node-limit`, an experiment's `node_limit`); nullopt: none given.
RunOutcome execute_run(const world::Problem& problem, const std::string& planner, const core::ParamMap& params,
                       std::uint64_t seed, double time_limit_s, std::optional<std::size_t> node_limit,
                       const PlannerRegistry& registry = builtin_planners(),
                       const std::atomic<bool>* cancel = nullptr);

// The node limit of a run: the run's own if given, else the problem's `defaults.node_limit` if its
// file gives one, else the planner's default (PlannerInfo::default_node_limit: 20000 for a roadmap,
// none for grid-dp). The one rule for plan, render, demo and bench.
std::size_t resolve_node_limit(std::optional<std::size_t> run_limit, const world::Problem& problem,
                               const PlannerInfo& planner);

// `params` plus the problem's parameter defaults (`defaults.params`) that the planner declares and
// `params` does not set: run settings override problem settings, which override planner defaults.
core::ParamMap with_problem_params(const world::Problem& problem, const PlannerInfo& planner, core::ParamMap params);

// Smallest clearance along `path`, sampling each segment at the space's resolution; 0 for an empty path.
double path_clearance(const core::Space& space, const world::ValidityChecker& checker, const std::vector<State>& path);

}  // namespace amp::roadmap
