// PGCS queries (Vlassis, Papakonstantinou & Tsanakas, section 4): the modified A* on the learned
// graph of the bundled office map after 200,000 exploration steps, as a query runs it on every
// replan, without the driving. Target: one query with its replans <= 1 ms.
// BM_PgcsRoutePlan: one plan between random free points on the portal graph (the portals' extra
// edges and exemplars, as the session plans; up to 1,000 clusters), on a new graph (/0: its
// neighbours found afresh) or a kept one (/1). BM_PgcsQueryPlanning/K: whole queries driven in the
// simulator with up to K clusters, reporting the planning time per query (counter plan_ms),
// replans and edges left out.
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <benchmark/benchmark.h>

#include "amp/core/rng.hpp"
#include "amp/nav/pgcs/pgcs_session.hpp"
#include "amp/nav/pgcs/portal_graph.hpp"
#include "amp/world/problem.hpp"
#include "support/source_tree.hpp"

namespace {

// A session per (maximum clusters, user), so that each benchmark draws the same queries whether or
// not the others ran before it.
amp::nav::PgcsSession& explored_office(int max_clusters, int user) {
  static std::map<std::pair<int, int>, std::unique_ptr<amp::nav::PgcsSession>> sessions;
  auto& s = sessions[{max_clusters, user}];
  if (!s) {
    const amp::world::Problem p = amp::world::load_problem(std::string(AMP_SOURCE_DIR) + "/problems/office-map.yaml");
    amp::nav::PgcsRunSettings run;
    run.steps = 200000;
    amp::learn::PgcsSettings pgcs;
    pgcs.max_clusters = max_clusters;
    s = std::make_unique<amp::nav::PgcsSession>(amp::nav::make_nav_task(p), run, pgcs, 1);
    s->explore(run.steps);
  }
  return *s;
}

// state.range(0): the plans share one graph (the neighbours found once are reused), or each plans
// on a new one.
void BM_PgcsRoutePlan(benchmark::State& state) {
  amp::nav::PgcsSession& s = explored_office(1000, 0);
  const auto pairs = s.draw_queries(256);
  amp::nav::RoutePlanner planner({0.25, 0.25, 3, 1.0});
  amp::nav::PortalGraph kept(s.explorer(), s.memory());
  std::size_t i = 0, expanded = 0;
  for (auto _ : state) {
    const auto& [a, b] = pairs[i++ % pairs.size()];
    amp::nav::Route r;
    if (state.range(0) != 0) {
      r = planner.plan(kept, a, b);
    } else {
      amp::nav::PortalGraph fresh(s.explorer(), s.memory());
      r = planner.plan(fresh, a, b);
    }
    expanded += r.expanded;
    benchmark::DoNotOptimize(r.cost);
  }
  state.counters["clusters"] = s.clusters().size();
  state.counters["expanded"] = benchmark::Counter(static_cast<double>(expanded), benchmark::Counter::kAvgIterations);
}
BENCHMARK(BM_PgcsRoutePlan)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

// state.range(0): the maximum number of clusters (1,000, the default; 200, the exploration target's).
void BM_PgcsQueryPlanning(benchmark::State& state) {
  amp::nav::PgcsSession& s = explored_office(static_cast<int>(state.range(0)), 1);
  const auto pairs = s.draw_queries(64);
  double plan = 0.0, replans = 0.0, left_out = 0.0;
  std::size_t n = 0;
  for (auto _ : state) {
    const auto& [a, b] = pairs[n++ % pairs.size()];
    const amp::nav::QueryRecord q = s.query(a, b);
    plan += q.plan_time_s;
    replans += q.replans;
    left_out += q.left_out;
  }
  state.counters["clusters"] = s.clusters().size();
  state.counters["plan_ms"] = 1e3 * plan / static_cast<double>(n);
  state.counters["replans"] = replans / static_cast<double>(n);
  state.counters["left_out"] = left_out / static_cast<double>(n);
}
BENCHMARK(BM_PgcsQueryPlanning)->Arg(1000)->Arg(500)->Arg(200)->Unit(benchmark::kMillisecond)->Iterations(64);

}  // namespace
