#include "amp/core/run_record.hpp"

#include "amp/core/error.hpp"

namespace amp::core {

std::string_view to_string(PlanStatus s) {
  switch (s) {
    case PlanStatus::kSolved: return "solved";
    case PlanStatus::kTimeout: return "timeout";
    case PlanStatus::kNodeLimit: return "node_limit";
    case PlanStatus::kUnsolvable: return "unsolvable";
    case PlanStatus::kError: return "error";
  }
  return "error";
}

PlanStatus plan_status_from_string(std::string_view s) {
  for (PlanStatus p : {PlanStatus::kSolved, PlanStatus::kTimeout, PlanStatus::kNodeLimit, PlanStatus::kUnsolvable,
                       PlanStatus::kError}) {
    if (to_string(p) == s) return p;
  }
  throw ParameterError("unknown run status '" + std::string(s) + "'");
}

void RunRecord::take_counters(const Counters& c) {
  cd_calls_training = c.cd_calls(Phase::kTraining);
  cd_calls_planning = c.cd_calls(Phase::kPlanning);
  cd_calls_query = c.cd_calls(Phase::kQuery);
  clearance_calls = c.clearance_calls();
  lp_calls = c.lp_calls();
  lp_successes = c.lp_successes();
}

}  // namespace amp::core
