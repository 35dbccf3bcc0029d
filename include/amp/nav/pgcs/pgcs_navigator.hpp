#pragma once
#include "amp/learn/pgcs.hpp"
#include "amp/nav/navigator.hpp"
#include "amp/nav/pgcs/pgcs_session.hpp"

namespace amp::nav {

// `pgcs` as a navigation method: one run explores `steps` steps from the problem's start, then
// drives `queries` random query pairs by trial and error (PgcsSession). Its record: status solved
// when every query was, path_length the length driven over the queries, nodes and edges the
// clusters and Delaunay edges, and in `extra` the metrics `amp explore` prints (replans, the
// median path ratio to the grid-shortest, coverage, ...).
class PgcsNavigator final : public Navigator {
 public:
  PgcsNavigator(PgcsRunSettings run, learn::PgcsSettings pgcs) : run_(run), pgcs_(pgcs) {}
  NavigationOutcome run(const NavTask& task, const core::StopCondition& stop, core::Rng& rng) override;

 private:
  PgcsRunSettings run_;
  learn::PgcsSettings pgcs_;
};

// The flat metrics of a finished session and its queries (what `amp explore` prints, and a run's
// record extras): steps, clusters, coverage, quantisation_error, queries, queries_solved,
// solved_fraction, replans, replans_median, replans_max, path_ratio_median, illegal_edges,
// query_time_median_s.
std::map<std::string, double> pgcs_metrics(const PgcsSession& session, const std::vector<QueryRecord>& queries);

}  // namespace amp::nav
