#pragma once
#include <string>
#include <string_view>

#include "amp/core/run_record.hpp"

namespace amp::bench {

// The metric an experiment names as its run cost (`cost:`, docs/experiment-format.md): the tests
// between methods and the report's Table 1, box plots and histograms use it.
inline constexpr std::string_view kDefaultCost = "cd_calls";

// A numeric column of runs.csv (cd_calls, wall_time_s, nodes, path_length, ...) is read from the
// record; any other identifier-like name is a key of the record's `extra`, which only the runs can
// show. Throws ParameterError for a name that is a non-numeric column (status, seed, ...) or not
// identifier-like (letters, digits, '_', '.', '-', starting with a letter or '_').
void check_cost_metric(const std::string& name);

// True for path_length and path_clearance: they are 0 without a path, so, as their columns of the
// summary, they are taken from solved runs only.
bool solved_only_metric(std::string_view name);

// One run's part in a metric's sample.
struct MetricSample {
  enum class Kind { kValue, kExcluded, kMissing };
  Kind kind = Kind::kMissing;
  double value = 0.0;
};

// The run's value of `name`: kExcluded for an unsolved run under a solved-only metric; kMissing for
// an extra the run does not have or holds as NaN or infinity (a median of no solved query, ...).
MetricSample metric_sample(const core::RunRecord& r, std::string_view name);

// How headings name the metric: "CD calls" for cd_calls, otherwise its name.
std::string metric_label(std::string_view name);

// Which way a metric improves. The tests between methods do not care, but every "best" of the
// summary and the report does: a method that solves 4 % of its worlds is not the best one.
enum class CostDirection { kLower, kHigher };

// The direction a metric has unless the experiment says otherwise (`cost_direction:`): higher for
// path_clearance and for an extra whose name has a word (split at '_', '.', '-') saying what was
// achieved (solved, success, successes, reached, arrived, clearance, coverage: solved_fraction,
// queries_solved, min_clearance, ...); lower for every other name (cd_calls, wall_time_s, steps_mean,
// path_length, lp_successes, which counts work, ...).
CostDirection default_cost_direction(std::string_view name);

// "higher" or "lower", as summary.json and experiment files write it.
std::string_view to_string(CostDirection d);
// Throws ParameterError for a word other than "higher" or "lower".
CostDirection parse_cost_direction(std::string_view word);

// True when a is strictly better than b under d (ties keep the earlier method).
inline bool better(CostDirection d, double a, double b) { return d == CostDirection::kHigher ? a > b : a < b; }

}  // namespace amp::bench
