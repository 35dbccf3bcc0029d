#include "amp/nav/navigator_catalog.hpp"

#include <chrono>

#include "amp/core/error.hpp"
#include "amp/core/rng.hpp"
#include "amp/core/stop_condition.hpp"

namespace amp::nav {

const NavigatorRegistry& builtin_navigators() {
  static const NavigatorRegistry registry = [] {
    NavigatorRegistry r;
    register_pgcs(r);
    register_policy_search(r);
    register_dwa(r);
    register_sins(r);
    return r;
  }();
  return registry;
}

NavigationOutcome execute_navigation(const world::Problem& problem, const std::string& method,
                                     const core::ParamMap& params, std::uint64_t seed, double time_limit_s,
                                     const NavigatorRegistry& registry, const std::atomic<bool>* cancel) {
  // Made before anything is timed: a bad name, parameter or problem throws here.
  std::unique_ptr<Navigator> navigator = registry.make(method, params);
  const NavTask task = make_nav_task(problem);
  NavigationOutcome out;
  core::Rng rng(seed);
  const auto t0 = std::chrono::steady_clock::now();
  try {
    const core::StopCondition stop(time_limit_s, static_cast<std::size_t>(-1), cancel);
    out = navigator->run(task, stop, rng);
  } catch (const ParameterError&) {
    throw;
  } catch (const std::exception& e) {
    out = NavigationOutcome{};
    out.record.status = core::PlanStatus::kError;
    out.record.message = e.what();
  }
  core::RunRecord& r = out.record;
  r.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.planner = method;
  r.problem = problem.name;
  r.seed = seed;
  r.path_states = out.trace.size();
  return out;
}

}  // namespace amp::nav
