#include "amp/nav/pgcs/pgcs_run.hpp"

#include <algorithm>
#include <chrono>

#include "amp/core/stop_condition.hpp"
#include "amp/stats/descriptive.hpp"

namespace amp::nav {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

bool fired(const core::StopCondition* stop) { return stop != nullptr && stop->fired(); }

void drive_queries(PgcsRun& r, const QueryPairs& pairs, bool given, const core::StopCondition* stop) {
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const auto q0 = Clock::now();
    try {
      r.queries.push_back(r.session->query(pairs[i].first, pairs[i].second, stop));
    } catch (const ParameterError& e) {
      if (!given) throw;
      throw PgcsQueryError(i, e.what());
    }
    r.query_wall_s.push_back(seconds_since(q0));
    if (fired(stop)) {
      r.stopped = true;
      return;
    }
  }
}

}  // namespace

PgcsRun run_pgcs(NavTask task, const PgcsRunSettings& run, const learn::PgcsSettings& pgcs, std::uint64_t seed,
                 const QueryPairs& given, const core::StopCondition* stop,
                 const std::function<void(long done, long total)>& progress) {
  PgcsRun r;
  r.session = std::make_unique<PgcsSession>(std::move(task), run, pgcs, seed);
  std::function<void(long)> explored_so_far;
  if (progress) explored_so_far = [&progress, &run](long done) { progress(done, run.steps); };
  const auto t0 = Clock::now();
  r.stopped = !r.session->explore(run.steps, stop, explored_so_far);
  r.explore_time_s = seconds_since(t0);
  if (r.stopped) return r;
  const bool use_given = !given.empty();
  drive_queries(r, use_given ? given : r.session->draw_queries(run.queries), use_given, stop);
  return r;
}

PgcsSummary summarise_pgcs(const PgcsSession& session, const std::vector<QueryRecord>& queries) {
  PgcsSummary s;
  std::vector<double> replans, ratios, times;
  for (const QueryRecord& q : queries) {
    replans.push_back(q.replans);
    s.replans_total += q.replans;
    s.replans_max = std::max(s.replans_max, q.replans);
    times.push_back(q.plan_time_s);
    if (q.solved) {
      ++s.queries_solved;
      ratios.push_back(q.ratio);
    }
  }
  s.steps = session.steps();
  s.clusters = session.clusters().size();
  s.coverage = session.coverage();
  s.quantisation_error = session.quantisation_error();
  s.illegal_edges = session.memory().size();
  s.suspect_edges = session.memory().suspects();
  s.queries = queries.size();
  s.replans_median = stats::median(replans);
  s.path_ratio_median = stats::median(ratios);
  s.query_time_median_s = stats::median(times);
  return s;
}

std::map<std::string, double> pgcs_metrics(const PgcsSummary& s) {
  const double n = static_cast<double>(s.queries);
  std::map<std::string, double> m = {{"steps", static_cast<double>(s.steps)},
                                     {"clusters", static_cast<double>(s.clusters)},
                                     {"coverage", s.coverage},
                                     {"quantisation_error", s.quantisation_error},
                                     {"queries", n},
                                     {"queries_solved", static_cast<double>(s.queries_solved)},
                                     {"solved_fraction", n > 0 ? s.queries_solved / n : 0.0},
                                     {"replans", s.replans_total},
                                     {"replans_max", static_cast<double>(s.replans_max)},
                                     {"illegal_edges", static_cast<double>(s.illegal_edges)},
                                     {"suspect_edges", static_cast<double>(s.suspect_edges)}};
  if (s.replans_median) m["replans_median"] = *s.replans_median;
  if (s.path_ratio_median) m["path_ratio_median"] = *s.path_ratio_median;
  return m;
}

}  // namespace amp::nav
