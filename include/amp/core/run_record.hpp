#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "amp/core/counters.hpp"
#include "amp/core/state.hpp"

namespace amp::core {

// How a run ended. No path is a status, not an exception.
enum class PlanStatus { kSolved, kTimeout, kNodeLimit, kUnsolvable, kError };

std::string_view to_string(PlanStatus s);
// Throws ParameterError for an unknown name.
PlanStatus plan_status_from_string(std::string_view s);

// The flat record every run reports (docs/experiment-format.md); `amp plan` prints it and `amp bench` writes
// one row of it per run.
struct RunRecord {
  std::string planner;
  std::string problem;
  std::uint64_t seed = 0;
  PlanStatus status = PlanStatus::kError;
  std::string message;  // error text for status kError, otherwise empty
  double wall_time_s = 0.0;
  std::uint64_t cd_calls_training = 0;
  std::uint64_t cd_calls_planning = 0;
  std::uint64_t cd_calls_query = 0;
  std::uint64_t clearance_calls = 0;
  std::uint64_t nodes = 0;
  std::uint64_t edges = 0;
  std::uint64_t components = 0;
  std::uint64_t lp_calls = 0;
  std::uint64_t lp_successes = 0;
  std::uint64_t path_states = 0;
  double path_length = 0.0;     // NaN-free: 0 when there is no path
  double path_clearance = 0.0;  // smallest clearance along the path, 0 when there is no path
  // Planner-specific figures (node types, regions, clusters, drawn parameters...), sorted by name.
  std::map<std::string, double> extra;

  std::uint64_t cd_calls() const { return cd_calls_training + cd_calls_planning + cd_calls_query; }
  // Copies the counters' totals into the record.
  void take_counters(const Counters& c);
};

}  // namespace amp::core
