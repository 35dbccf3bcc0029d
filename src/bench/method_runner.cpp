#include "amp/bench/method_runner.hpp"

#include "amp/core/error.hpp"
#include "amp/nav/navigator_catalog.hpp"
#include "amp/roadmap/run.hpp"
#include "amp/study/navigation_run.hpp"

namespace amp::bench {

MethodKind method_kind(const std::string& name) {
  const bool planner = roadmap::builtin_planners().contains(name);
  const bool navigator = nav::builtin_navigators().contains(name);
  if (planner && navigator) {
    throw ParameterError("'" + name + "' is both a planner and a navigation method; the catalogs must not share names");
  }
  if (planner) return MethodKind::kPlanner;
  if (navigator) return MethodKind::kNavigator;
  auto list = [](const std::vector<std::string>& names) {
    std::string s;
    for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
    return s.empty() ? std::string("none") : s;
  };
  throw ParameterError("unknown planner or navigation method '" + name + "' (planners: " +
                       list(roadmap::builtin_planners().names()) + "; navigation methods: " +
                       list(nav::builtin_navigators().names()) + ")");
}

MethodRun run_method(const world::Problem& problem, MethodKind kind, const std::string& method,
                     const core::ParamMap& params, std::uint64_t seed, double time_limit_s,
                     std::optional<std::size_t> node_limit,
                     const std::atomic<bool>* cancel) {
  MethodRun out;
  switch (kind) {
    case MethodKind::kPlanner: {
      roadmap::RunOutcome run = roadmap::execute_run(problem, method, params, seed, time_limit_s, node_limit,
                                                     roadmap::builtin_planners(), cancel);
      out.record = std::move(run.record);
      out.path = std::move(run.path);
      break;
    }
    case MethodKind::kNavigator: {
      nav::NavigationOutcome run = study::run_navigation(problem, method, params, seed, time_limit_s, cancel);
      out.record = std::move(run.record);
      out.path.reserve(run.trace.size());
      for (const Eigen::Vector2d& p : run.trace) out.path.push_back(State(p));
      break;
    }
  }
  return out;
}

}  // namespace amp::bench
