#pragma once
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "amp/bench/experiment.hpp"
#include "amp/core/parameters.hpp"
#include "amp/core/run_record.hpp"
#include "amp/core/state.hpp"
#include "amp/world/problem.hpp"

namespace amp::bench {

// Which catalog a method of an experiment comes from: roadmap::builtin_planners() or
// nav::builtin_navigators(). Throws ParameterError for a name in neither (listing both catalogs'
// names) or in both (the experiment could not say which one it means).
MethodKind method_kind(const std::string& name);

struct MethodRun {
  core::RunRecord record;
  std::vector<State> path;  // a planner's path, or a navigator's driven trace as 2-D states
};

// One run of `method` as `amp bench` does it: roadmap::execute_run for a planner,
// nav::execute_navigation for a navigation method, with the same seed, time limit and cancel flag
// (navigators have no node limit; a planner's is roadmap::resolve_node_limit(node_limit, ...)).
// Errors propagate as those two functions throw them.
MethodRun run_method(const world::Problem& problem, MethodKind kind, const std::string& method,
                     const core::ParamMap& params, std::uint64_t seed, double time_limit_s,
                     std::optional<std::size_t> node_limit,
                     const std::atomic<bool>* cancel);

}  // namespace amp::bench
