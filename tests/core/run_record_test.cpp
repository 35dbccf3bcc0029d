// run_record.cpp: a run's status by name, and the counters a record takes.
#include "amp/core/run_record.hpp"

#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"

namespace amp::core {
namespace {

TEST(RunRecord, StatusNamesRoundTrip) {
  const std::pair<PlanStatus, const char*> names[] = {{PlanStatus::kSolved, "solved"},
                                                      {PlanStatus::kTimeout, "timeout"},
                                                      {PlanStatus::kNodeLimit, "node_limit"},
                                                      {PlanStatus::kUnsolvable, "unsolvable"},
                                                      {PlanStatus::kError, "error"}};
  for (const auto& [status, name] : names) {
    EXPECT_EQ(to_string(status), name);
    EXPECT_EQ(plan_status_from_string(name), status);
  }
  try {
    plan_status_from_string("Solved");
    FAIL() << "'Solved' was accepted";
  } catch (const ParameterError& e) {
    EXPECT_EQ(std::string(e.what()), "unknown run status 'Solved'");
  }
}

TEST(RunRecord, TakesEachPhasesCdCallsAndTheLocalPlannerFigures) {
  Counters c;
  c.set_phase(Phase::kTraining);
  for (int i = 0; i < 3; ++i) c.add_cd_call();
  c.set_phase(Phase::kPlanning);
  for (int i = 0; i < 5; ++i) c.add_cd_call();
  c.add_local_plan(true);
  c.add_local_plan(false);
  c.add_local_plan(true);
  c.set_phase(Phase::kQuery);
  c.add_cd_call();
  c.add_clearance_call();
  c.add_clearance_call();
  RunRecord r;
  r.nodes = 42;  // not a counter: left alone
  r.take_counters(c);
  EXPECT_EQ(r.cd_calls_training, 3u);
  EXPECT_EQ(r.cd_calls_planning, 5u);
  EXPECT_EQ(r.cd_calls_query, 1u);
  EXPECT_EQ(r.cd_calls(), 9u);
  EXPECT_EQ(r.clearance_calls, 2u);
  EXPECT_EQ(r.lp_calls, 3u);
  EXPECT_EQ(r.lp_successes, 2u);
  EXPECT_EQ(r.nodes, 42u);
  EXPECT_EQ(r.status, PlanStatus::kError);  // a record is an error until a run says otherwise
}

}  // namespace
}  // namespace amp::core
