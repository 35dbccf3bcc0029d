#include "amp/roadmap/run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "amp/core/edge_steps.hpp"
#include "amp/core/error.hpp"
#include "amp/core/stop_condition.hpp"
#include "amp/roadmap/prm/path_smoothing.hpp"

namespace amp::roadmap {

namespace {
// At most this many clearance samples per path: the bundled paths need up to 3541; 4096 calls of
// the dearest checker (SCARA, 30 us) take 0.12 s, so the measurement cannot outlast a run.
constexpr double kMaxClearanceSamples = 4096;
}  // namespace

double path_clearance(const core::Space& space, const world::ValidityChecker& checker, const std::vector<State>& path) {
  if (path.empty()) return 0.0;
  double best = checker.clearance(path.front()).distance;
  const double step = std::max(space.resolution(), path_length(space, path) / kMaxClearanceSamples);
  State s;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const std::int64_t segments =
        std::max<std::int64_t>(1, core::edge_segments(space.distance(path[i - 1], path[i]), step));
    for (std::int64_t j = 1; j <= segments; ++j) {
      space.interpolate(path[i - 1], path[i], static_cast<double>(j) / static_cast<double>(segments), s);
      best = std::min(best, checker.clearance(s).distance);
    }
  }
  return best;
}

core::ParamMap with_problem_params(const world::Problem& problem, const PlannerInfo& planner, core::ParamMap params) {
  for (const auto& [name, value] : problem.defaults.params) {
    const bool declared = std::any_of(planner.params.begin(), planner.params.end(),
                                      [&key = name](const core::ParamSpec& s) { return s.name == key; });
    if (declared) params.emplace(name, value);  // emplace keeps a value the run set
  }
  return params;
}

std::size_t resolve_node_limit(std::optional<std::size_t> run_limit, const world::Problem& problem,
                               const PlannerInfo& planner) {
  return run_limit.value_or(problem.defaults.node_limit.value_or(planner.default_node_limit));
}

RunOutcome execute_run(const world::Problem& problem, const std::string& planner, const core::ParamMap& params,
                       std::uint64_t seed, double time_limit_s, std::optional<std::size_t> node_limit,
                       const PlannerRegistry& registry, const std::atomic<bool>* cancel) {
  if (!problem.space || !problem.environment) {
    throw Error("problem '" + problem.name + "': no space or environment");
  }
  // Made before anything is timed: a bad planner name or parameter throws ParameterError here.
  const PlannerInfo& info = registry.info(planner);
  std::unique_ptr<Planner> p = registry.make(planner, with_problem_params(problem, info, params));
  const std::size_t nodes = resolve_node_limit(node_limit, problem, info);

  RunOutcome out;
  core::RunRecord& r = out.record;
  r.planner = planner;
  r.problem = problem.name;
  r.seed = seed;

  core::Counters counters;
  counters.set_phase(core::Phase::kPlanning);
  const std::unique_ptr<world::ValidityChecker> checker = problem.environment->make_checker(counters);
  core::Rng rng(seed);

  const auto t0 = std::chrono::steady_clock::now();
  PlanResult result;
  if (!problem.unsolvable_because.empty()) {
    result.status = core::PlanStatus::kUnsolvable;
    r.message = problem.unsolvable_because;
  } else {
    try {
      const core::StopCondition stop(time_limit_s, nodes, cancel);
      const PlanningContext ctx{*problem.space, *problem.environment, *checker, problem.seeds,
                                problem.defaults.edge_check, &stop};
      result = p->plan(ctx, stop, rng);
    } catch (const InvalidSeedError&) {
      throw;
    } catch (const ParameterError&) {
      throw;
    } catch (const std::exception& e) {
      result = PlanResult{};
      result.status = core::PlanStatus::kError;
      r.message = e.what();
    }
  }
  r.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  r.status = result.status;
  r.take_counters(counters);
  r.nodes = result.nodes;
  r.edges = result.edges;
  r.components = result.components;
  r.extra = std::move(result.extra);
  for (const auto& [key, value] : problem.record_extra) r.extra[key] = value;
  if (result.status == core::PlanStatus::kSolved) {
    r.path_states = result.path.size();
    r.path_length = path_length(*problem.space, result.path);
    core::Counters measuring;  // clearance measured outside the run's counters
    const auto clearance_checker = problem.environment->make_checker(measuring);
    r.path_clearance = path_clearance(*problem.space, *clearance_checker, result.path);
    out.path = std::move(result.path);
  }
  out.roadmap = std::move(result.roadmap);
  return out;
}

}  // namespace amp::roadmap
