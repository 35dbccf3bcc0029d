#pragma once
// Private to the report (src/bench/report*.cpp): the parts of report.html other than the header
// and the problem drawing.
#include <cstddef>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "amp/bench/experiment.hpp"

namespace amp::bench::report_page {

// From runs.csv: cost[problem][planner] = each run's cost (Experiment::cost; runs without a value of
// it left out); the first solved trial per problem.
struct RunData {
  std::vector<std::vector<std::vector<double>>> cost;
  std::vector<std::optional<std::size_t>> first_solved;
  // first_run_solved[problem][planner]: the trial index of the row's first run (run 0, the first
  // seed) when it solved with a path (a planner, not a navigation method or a sequence of worlds).
  std::vector<std::vector<std::optional<std::size_t>>> first_run_solved;
  bool found = false;  // runs.csv exists (the report can be written from summary.json alone)
};

extern const char* const kStyle;  // the page's whole stylesheet

// The colour of planner configuration `i` in every table swatch and chart of the page.
std::string planner_color(std::size_t i);

// Planner configurations and a problems x planners matrix of mean cost, CV and solved % (the best
// mean marked in the cost's direction, the lowest CV).
void overview(std::ostream& out, const Experiment& e, const nlohmann::json& problems);
// The paper's Table 1 for one problem (summary.json's entry) on the experiment's cost, the best mean
// marked in the cost's direction, extended with the five-number summary and median time, nodes and
// path length; a note when some method's runs are sequences of worlds.
void cost_table(std::ostream& out, const Experiment& e, const nlohmann::json& problem);
// Every other metric the methods report (summary.json's "metrics"): median and quartiles per method,
// descriptive only. Nothing when no method reports one.
void metrics_table(std::ostream& out, const nlohmann::json& problem);
// Nodes and CD calls split into training and planning (medians), shown only when some planner of
// the problem spent CD calls in a training phase.
void phase_table(std::ostream& out, const nlohmann::json& problem);
// Box plot of every planner's run cost and one histogram per planner on shared bins and axes; a
// log scale when the costs span more than kLogSpan.
void charts(std::ostream& out, const Experiment& e, const std::vector<std::vector<double>>& cost);
inline constexpr double kLogSpan = 30.0;

// For a 3-D problem: each row's first run, when it solved, re-run from its seed and written as a
// 3-D viewer page into dir/viewer/ (viz::viewer_page); returns the paragraph linking the pages
// (empty for a 2-D problem or when no row's first run solved).
std::string viewer_links(const Experiment& e, std::size_t problem, const RunData& runs,
                         const std::filesystem::path& dir);

}  // namespace amp::bench::report_page
