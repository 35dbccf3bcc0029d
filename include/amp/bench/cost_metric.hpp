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

}  // namespace amp::bench
