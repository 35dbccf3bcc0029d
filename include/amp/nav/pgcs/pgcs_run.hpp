#pragma once
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "amp/core/error.hpp"
#include "amp/learn/pgcs.hpp"
#include "amp/nav/pgcs/pgcs_session.hpp"

namespace amp::core {
class StopCondition;
}

namespace amp::nav {

// One PGCS run, the one loop `amp explore`, the `pgcs` navigation method and Python share: explore
// `run.steps` steps from the task's start, then drive the query pairs (the given ones, or
// run.queries pairs drawn from the session) by trial and error.
struct PgcsRun {
  std::unique_ptr<PgcsSession> session;
  std::vector<QueryRecord> queries;
  std::vector<double> query_wall_s;  // each query's wall time, driving included
  double explore_time_s = 0.0;
  bool stopped = false;  // `stop` fired: exploration or a query was cut short
};

// A given query the session refuses (a point outside the world, or not free once a door closed
// during exploration): the pair's index, so that a caller can name its own option.
class PgcsQueryError : public ParameterError {
 public:
  PgcsQueryError(std::size_t index, const std::string& detail)
      : ParameterError("query " + std::to_string(index + 1) + ": " + detail), index_(index), detail_(detail) {}
  std::size_t index() const { return index_; }
  const std::string& detail() const { return detail_; }

 private:
  std::size_t index_;
  std::string detail_;
};

using QueryPairs = std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>>;
PgcsRun run_pgcs(NavTask task, const PgcsRunSettings& run, const learn::PgcsSettings& pgcs, std::uint64_t seed,
                 const QueryPairs& given = {}, const core::StopCondition* stop = nullptr,
                 const std::function<void(long done, long total)>& progress = {});

// The summary of a finished run (the one copy: `amp explore`'s record and the `pgcs` method's
// extras). A median of no sample (no query, or none solved: no path ratio) is none.
struct PgcsSummary {
  long steps = 0;
  std::size_t clusters = 0;
  double coverage = 0.0;
  double quantisation_error = 0.0;
  std::size_t illegal_edges = 0;
  std::size_t suspect_edges = 0;
  std::size_t queries = 0;
  int queries_solved = 0;
  double replans_total = 0.0;
  int replans_max = 0;
  std::optional<double> replans_median;
  std::optional<double> path_ratio_median;
  std::optional<double> query_time_median_s;  // route planning only; driving is simulated time
};
PgcsSummary summarise_pgcs(const PgcsSession& session, const std::vector<QueryRecord>& queries);

// The summary as a run's record extras: steps, clusters, coverage, quantisation_error, queries,
// queries_solved, solved_fraction, replans, replans_median, replans_max, path_ratio_median,
// illegal_edges, suspect_edges (no timing). A median of no sample is left out.
std::map<std::string, double> pgcs_metrics(const PgcsSummary& summary);

}  // namespace amp::nav
