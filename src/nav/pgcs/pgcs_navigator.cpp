#include "amp/nav/pgcs/pgcs_navigator.hpp"

#include <algorithm>

#include "amp/core/rng.hpp"
#include "amp/core/stop_condition.hpp"
#include "amp/nav/navigator_catalog.hpp"

namespace amp::nav {

namespace {
// Type-7 median (R's default), 0 for an empty sample.
double median(std::vector<double> x) {
  if (x.empty()) return 0.0;
  std::sort(x.begin(), x.end());
  const std::size_t n = x.size();
  return n % 2 == 1 ? x[n / 2] : 0.5 * (x[n / 2 - 1] + x[n / 2]);
}
}  // namespace

std::map<std::string, double> pgcs_metrics(const PgcsSession& session, const std::vector<QueryRecord>& queries) {
  std::vector<double> replans, ratios, times;
  double solved = 0.0, replans_total = 0.0, replans_max = 0.0;
  for (const QueryRecord& q : queries) {
    replans.push_back(q.replans);
    replans_total += q.replans;
    replans_max = std::max<double>(replans_max, q.replans);
    times.push_back(q.plan_time_s);
    if (q.solved) {
      solved += 1.0;
      ratios.push_back(q.ratio);
    }
  }
  const double n = static_cast<double>(queries.size());
  return {{"steps", static_cast<double>(session.steps())},
          {"clusters", static_cast<double>(session.clusters().size())},
          {"coverage", session.coverage()},
          {"quantisation_error", session.quantisation_error()},
          {"queries", n},
          {"queries_solved", solved},
          {"solved_fraction", n > 0 ? solved / n : 0.0},
          {"replans", replans_total},
          {"replans_median", median(replans)},
          {"replans_max", replans_max},
          {"path_ratio_median", median(ratios)},
          {"illegal_edges", static_cast<double>(session.memory().size())},
          {"suspect_edges", static_cast<double>(session.memory().suspects())},
          {"query_time_median_s", median(times)}};
}

NavigationOutcome PgcsNavigator::run(const NavTask& task, const core::StopCondition& stop, core::Rng& rng) {
  NavigationOutcome out;
  PgcsSession session(task, run_, pgcs_, rng.next_u64());
  const bool explored = session.explore(run_.steps, &stop);
  std::vector<QueryRecord> queries;
  bool stopped = !explored;
  if (explored) {
    for (const auto& [s, t] : session.draw_queries(run_.queries)) {
      queries.push_back(session.query(s, t, &stop));
      if (stop.fired()) {
        stopped = true;
        break;
      }
    }
  }
  core::RunRecord& r = out.record;
  r.extra = pgcs_metrics(session, queries);
  // Timings stay out of the record (wall_time_s has the run's): its other columns depend on the
  // seed alone, so runs.csv is the same whatever the threads, shards or machine.
  r.extra.erase("query_time_median_s");
  r.nodes = static_cast<std::uint64_t>(session.clusters().size());
  r.edges = session.clusters().triangulation().edges().size();
  for (const QueryRecord& q : queries) r.path_length += q.length;
  const bool all = std::all_of(queries.begin(), queries.end(), [](const QueryRecord& q) { return q.solved; });
  r.status = stopped ? core::PlanStatus::kTimeout : all ? core::PlanStatus::kSolved : core::PlanStatus::kUnsolvable;
  out.trace = session.exploration_trace();
  return out;
}

void register_pgcs(NavigatorRegistry& registry) {
  std::vector<core::ParamSpec> specs = PgcsRunSettings::schema().specs();
  for (const core::ParamSpec& s : learn::PgcsSettings::schema().specs()) specs.push_back(s);
  registry.add({"pgcs",
                "PGCS (Vlassis, Papakonstantinou & Tsanakas): a disc robot explores, learns the Voronoi centres of its "
                "free space, and answers queries on their Delaunay graph by trial and error",
                specs},
               [](const core::Params& p) -> std::unique_ptr<Navigator> {
                 return std::make_unique<PgcsNavigator>(PgcsRunSettings::schema().read(p),
                                                        learn::PgcsSettings::schema().read(p));
               });
}

}  // namespace amp::nav
