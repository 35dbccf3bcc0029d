#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "amp/core/parameters.hpp"
#include "amp/nav/navigator.hpp"
#include "amp/world/problem.hpp"

namespace amp::study {

// The two methods of "Policy search seeded by a value function", as `amp navigate` names them.
inline constexpr const char* kPolicyMethod = "policy-search";
inline constexpr const char* kDwaMethod = "dwa";

// One `amp navigate` run, shared with `amp demo`.
struct NavigateSetup {
  int runs = 50;
  std::uint64_t seed = 1;
  core::ParamMap params;  // each method takes those it declares (the drive settings are shared)
};

// One method over every seed: its flat record (a row of Table 2), each run's details, and the
// first run's plan stages, velocity profile and driven trace.
struct MethodRuns {
  nlohmann::json record;
  nlohmann::json runs = nlohmann::json::array();
  std::vector<nav::PlanStage> stages;
  std::vector<double> speeds;
  std::vector<Eigen::Vector2d> trace;
  bool arrived = false;  // the first run's
};

struct NavigateResult {
  MethodRuns policy, dwa;
};

// The parameters each method declares (the drive settings are both's). One neither declares throws
// ParameterError "unknown parameter 'x' (valid: ...)" (core::route_params).
struct NavigateParams {
  core::ParamMap policy, dwa;
};
NavigateParams route_navigate_params(const core::ParamMap& params);

// Both methods on the same seeds (run i's noise from derive_seed(seed, i)). Throws what the methods
// throw for bad input (ParameterError with one line), and Error for a run that fails otherwise.
NavigateResult run_both_methods(const world::Problem& problem, const NavigateSetup& setup);

// The paper's Table 2 as printed text, one row per method.
std::string format_table2(const NavigateResult& r, const NavigateSetup& setup);

// The files `-o DIR` gets, in the order they are written.
const std::vector<std::string>& navigate_output_files();

// record.json: `method`'s record, the parameters, Table 2 (both methods' records) and each run.
nlohmann::json navigate_record(const NavigateResult& r, const std::string& method, const NavigateSetup& setup);

// record.json (`method`'s record, its runs, the parameters, and Table 2), phases.svg (Figure 3) and
// velocity.svg (Figure 4) into `dir`, which is created.
void write_navigate_outputs(const world::Problem& problem, const NavigateResult& r, const std::string& method,
                            const NavigateSetup& setup, const std::filesystem::path& dir);

}  // namespace amp::study
