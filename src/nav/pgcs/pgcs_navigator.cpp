#include "amp/nav/pgcs/pgcs_navigator.hpp"

#include <algorithm>

#include "amp/core/rng.hpp"
#include "amp/core/stop_condition.hpp"
#include "amp/nav/navigator_catalog.hpp"
#include "amp/nav/pgcs/pgcs_run.hpp"

namespace amp::nav {

NavigationOutcome PgcsNavigator::run(const NavTask& task, const core::StopCondition& stop, core::Rng& rng) {
  NavigationOutcome out;
  const PgcsRun run = run_pgcs(task, run_, pgcs_, rng.next_u64(), {}, &stop);
  const PgcsSession& session = *run.session;
  core::RunRecord& r = out.record;
  // Timings stay out of the record (wall_time_s has the run's): its other columns depend on the
  // seed alone, so runs.csv is the same whatever the threads, shards or machine.
  r.extra = pgcs_metrics(summarise_pgcs(session, run.queries));
  r.nodes = static_cast<std::uint64_t>(session.clusters().size());
  r.edges = session.clusters().triangulation().edges().size();
  for (const QueryRecord& q : run.queries) r.path_length += q.length;
  const bool all = std::all_of(run.queries.begin(), run.queries.end(), [](const QueryRecord& q) { return q.solved; });
  r.status = run.stopped ? core::PlanStatus::kTimeout : all ? core::PlanStatus::kSolved : core::PlanStatus::kUnsolvable;
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
