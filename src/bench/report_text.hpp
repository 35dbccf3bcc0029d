#pragma once
// Private to the report (src/bench/report*.cpp): numbers as the page prints them, and the tests
// of summary.json in words.
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "amp/bench/cost_metric.hpp"

namespace amp::bench::report_text {

// A statistic of summary.json: NaN when the key is missing or null (JSON has no NaN).
double number_at(const nlohmann::json& j, const char* key);

// "a", "a and b", "a, b and c".
std::string join_words(const std::vector<std::string>& items);

// Every formatter prints a non-finite value as an en dash, never "nan".
std::string count(double v);             // 2,021,367 (grouped, whole) from 100 on; 12.5 below
std::string statistic(double v);         // F or H: 5.04, 12.3, 718
std::string degrees_of_freedom(double v);  // 717 or 451.3
std::string p_value(double p);           // "p = 0.0071", "p < 0.0001"
std::string percent(double v);           // "31 %", "66.7 %", "4.2 %"
std::string seconds(double v);           // "0.42 ms", "12.3 ms", "1.23 s"
std::string real(double v);              // 4 significant digits: 123.4, 0.01234

// How the page names and prints the experiment's cost (Experiment::cost, bench/cost_metric.hpp).
struct CostStyle {
  std::string label = "CD calls";  // in headings and sentences: "CD calls", or the metric's name
  bool is_time = false;            // wall_time_s: printed as seconds, other metrics as count()
  CostDirection direction = CostDirection::kLower;
  std::string format(double v) const { return is_time ? seconds(v) : count(v); }
  bool higher() const { return direction == CostDirection::kHigher; }
  // What sentences call it: "run cost" (the run-cost paper's word) when lower is better, else the
  // metric's label, since a share of worlds solved is no cost. Not escaped.
  std::string quantity() const { return higher() ? label : "run cost"; }
};
CostStyle cost_style(const std::string& metric, CostDirection direction);

// What one run of a method is, for the page's words: a planning run, a navigation run, or a whole
// sequence of worlds (a navigation method whose runs report the `worlds` extra, as SINS's do), whose
// status "solved" says the sequence is complete, not that its worlds were solved.
enum class RunKind { kPlanning, kNavigation, kWorldSequence };
inline constexpr const char* kWorldsExtra = "worlds";
RunKind run_kind(const nlohmann::json& planner);  // from summary.json's entry of the method

// The cost's statistics in one planner entry of summary.json: its "cost" object when the experiment
// names a cost other than CD calls, otherwise "cd_calls"; an empty object when neither is there.
const nlohmann::json& cost_json(const nlohmann::json& planner);

// The findings of one problem of summary.json, as HTML fragments (text escaped, planner names in
// <strong>): the best mean (lowest or highest, as the cost's direction says) and the lowest CV,
// unsolved runs, then each test between planners in words, at the REGWQ level alpha, e.g.
// "Brown–Forsythe test ...: the variances of run cost differ significantly (F(2, 717) = 5.04,
// p = 0.0071)". A problem with one planner, or tests skipped or degenerate, gets a sentence saying so.
std::vector<std::string> findings(const nlohmann::json& problem, const CostStyle& cost);

}  // namespace amp::bench::report_text
