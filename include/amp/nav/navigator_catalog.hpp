#pragma once
#include <atomic>
#include <cstdint>
#include <string>

#include "amp/core/method_catalog.hpp"
#include "amp/nav/navigator.hpp"

namespace amp::nav {

// The navigation methods by name, beside the roadmap planners (roadmap::builtin_planners()).
class NavigatorRegistry : public core::MethodCatalog<Navigator> {
 public:
  NavigatorRegistry() : core::MethodCatalog<Navigator>("navigation method") {}
};

// Every navigation method of the library, built once on first use and immutable afterwards.
const NavigatorRegistry& builtin_navigators();

// `pgcs` (pgcs/pgcs_navigator.hpp).
void register_pgcs(NavigatorRegistry& registry);
// `policy-search` (policy/policy_navigator.hpp).
void register_policy_search(NavigatorRegistry& registry);
// `dwa` (dwa/dwa_navigator.hpp).
void register_dwa(NavigatorRegistry& registry);
// `static`, `random` and `sins`: SINS's three systems, a run a sequence of worlds (sins/sins_navigator.hpp).
void register_sins(NavigatorRegistry& registry);

// One run of a navigation method on a problem, as `amp bench` does it: the task made from the
// problem, Rng(seed), a StopCondition(time_limit_s), the run timed and the record's identity
// filled. A bad method name or parameter (ParameterError) or a problem the method cannot take
// (not a disc robot, ...) is rethrown; a method that throws otherwise gives status kError.
NavigationOutcome execute_navigation(const world::Problem& problem, const std::string& method,
                                     const core::ParamMap& params, std::uint64_t seed, double time_limit_s,
                                     const NavigatorRegistry& registry = builtin_navigators(),
                                     const std::atomic<bool>* cancel = nullptr);

}  // namespace amp::nav
