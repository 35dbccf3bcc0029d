#pragma once
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "amp/bench/cost_metric.hpp"
#include "amp/core/run_record.hpp"
#include "amp/core/parameters.hpp"
#include "amp/world/problem.hpp"

namespace amp::bench {

// Where a method of an experiment is registered: roadmap::builtin_planners() or
// nav::builtin_navigators() (bench/method_runner.hpp tells and runs them).
enum class MethodKind { kPlanner, kNavigator };

// One method configuration of an experiment: a registered planner or navigation method with fixed
// parameters, and optionally parameters drawn uniformly per run from a set (the "metaplanner" of the
// run-cost paper).
struct PlannerConfig {
  std::string label;  // unique in the experiment; names the configuration in every output
  std::string planner;  // name in the PlannerRegistry or the NavigatorRegistry (see `kind`)
  core::ParamMap params;
  std::map<std::string, std::vector<core::ParamValue>> draws;
  MethodKind kind = MethodKind::kPlanner;
};

struct ExperimentProblem {
  std::string label;  // the problem's name (unique in the experiment)
  std::filesystem::path file;
  std::shared_ptr<const world::Problem> problem;  // loaded once, shared by every trial
  // Further files the problem is read from (an arm's scene beside its request: `file`), which the
  // experiment's fingerprint covers too.
  std::vector<std::filesystem::path> inputs;
};

// Problems x planner configurations x runs (docs/experiment-format.md).
struct Experiment {
  std::string name;
  std::filesystem::path file;
  std::uint64_t seed = 1;  // master seed
  int runs = 50;
  double time_limit_s = 30.0;
  // Not given: each run gets its problem's defaults.node_limit, else its planner's default
  // (roadmap::resolve_node_limit).
  std::optional<std::size_t> node_limit;
  // Common random numbers: run i of every planner configuration on a problem gets the same seed, so
  // that planners which spend their first random numbers alike (UAS's training roadmap under each
  // clustering method) can be compared run by run (paired tests). Off: each configuration its own.
  bool common_seeds = false;
  // The metric the tests and the report's cost charts use (`cost:`; bench/cost_metric.hpp).
  std::string cost = "cd_calls";
  // Which values of the cost are better (`cost_direction:`, else default_cost_direction(cost)). It
  // changes no run, only what the summary and the report call best, so it is not in the fingerprint.
  CostDirection cost_direction = CostDirection::kLower;
  std::vector<ExperimentProblem> problems;
  std::vector<PlannerConfig> planners;
  // Hash of everything that decides the results (not of the file's layout or comments): shards and
  // resumed runs must share it.
  std::string fingerprint;

  std::size_t trial_count() const { return problems.size() * planners.size() * static_cast<std::size_t>(runs); }
};

// Where a trial sits in the experiment. Trials are numbered problem-major, then planner, then run.
struct TrialId {
  std::size_t index = 0;
  std::size_t problem = 0;
  std::size_t planner = 0;
  int run = 0;
};

TrialId trial_id(const Experiment& e, std::size_t index);

// The trial's seed: SplitMix64 over FNV-1a(problem label, planner label) and the run index, mixed
// with the master seed. It depends on the trial's identity only, so results do not depend on the
// number of threads, shards or processes, nor on the order of problems in the file.
std::uint64_t trial_seed(const Experiment& e, const TrialId& id);

// The parameters a trial runs with: the configuration's fixed ones plus one value drawn uniformly
// (from an Rng seeded by the trial seed) for every drawn parameter, in name order.
core::ParamMap trial_params(const Experiment& e, const TrialId& id, std::map<std::string, std::string>* drawn);

// One finished trial as the outputs see it.
struct Trial {
  TrialId id;
  std::uint64_t seed = 0;
  std::map<std::string, std::string> drawn;  // drawn parameter values, as text
  core::RunRecord record;
};

// The hash stored in Experiment::fingerprint; recompute it after changing runs or limits.
std::string experiment_fingerprint(const Experiment& e);

// Parses and checks an experiment file: every problem file exists and loads, every planner or
// navigation method and parameter is known and in range (by building each method once), every
// problem can be taken by each navigation method, and the cost is a metric's name. Throws
// FileError/ParameterError.
Experiment load_experiment(const std::filesystem::path& file);

}  // namespace amp::bench
