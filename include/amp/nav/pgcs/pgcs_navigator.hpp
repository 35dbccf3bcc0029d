#pragma once
#include "amp/learn/pgcs.hpp"
#include "amp/nav/navigator.hpp"
#include "amp/nav/pgcs/pgcs_session.hpp"

namespace amp::nav {

// `pgcs` as a navigation method: one run_pgcs (pgcs_run.hpp), which explores `steps` steps from
// the problem's start, then drives `queries` random query pairs by trial and error. Its record:
// status solved when every query was, path_length the length driven over the queries, nodes and
// edges the clusters and Delaunay edges, and in `extra` pgcs_metrics (the summary `amp explore`
// prints: replans, the median path ratio to the grid-shortest, coverage, ...) but no timing: the
// run's wall_time_s is its time, and every other column depends on the seed alone.
class PgcsNavigator final : public Navigator {
 public:
  PgcsNavigator(PgcsRunSettings run, learn::PgcsSettings pgcs) : run_(run), pgcs_(pgcs) {}
  NavigationOutcome run(const NavTask& task, const core::StopCondition& stop, core::Rng& rng) override;

 private:
  PgcsRunSettings run_;
  learn::PgcsSettings pgcs_;
};

}  // namespace amp::nav
