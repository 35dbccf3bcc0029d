#include "amp/study/navigation_run.hpp"

#include "amp/nav/navigator_catalog.hpp"

namespace amp::study {

nav::NavigationOutcome run_navigation(const world::Problem& problem, const std::string& method,
                                      const core::ParamMap& params, std::uint64_t seed, double time_limit_s,
                                      const std::atomic<bool>* cancel) {
  return nav::execute_navigation(problem, method, params, seed, time_limit_s, nav::builtin_navigators(), cancel);
}

}  // namespace amp::study
