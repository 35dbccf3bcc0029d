#include "amp/bench/cost_metric.hpp"

#include <cctype>
#include <cmath>
#include <cstdint>
#include <optional>

#include "amp/core/error.hpp"

namespace amp::bench {

namespace {

// The record's numeric columns, by their runs.csv names; nullopt for any other name.
std::optional<double> column(const core::RunRecord& r, std::string_view name) {
  auto u = [](std::uint64_t v) { return static_cast<double>(v); };
  if (name == "cd_calls") return u(r.cd_calls());
  if (name == "wall_time_s") return r.wall_time_s;
  if (name == "cd_calls_training") return u(r.cd_calls_training);
  if (name == "cd_calls_planning") return u(r.cd_calls_planning);
  if (name == "cd_calls_query") return u(r.cd_calls_query);
  if (name == "clearance_calls") return u(r.clearance_calls);
  if (name == "nodes") return u(r.nodes);
  if (name == "edges") return u(r.edges);
  if (name == "components") return u(r.components);
  if (name == "lp_calls") return u(r.lp_calls);
  if (name == "lp_successes") return u(r.lp_successes);
  if (name == "path_states") return u(r.path_states);
  if (name == "path_length") return r.path_length;
  if (name == "path_clearance") return r.path_clearance;
  return std::nullopt;
}

// The other columns of runs.csv: identity and text, no cost.
bool text_column(std::string_view name) {
  for (std::string_view c : {"trial", "problem", "planner", "planner_type", "run", "seed", "status", "extra",
                             "message"}) {
    if (name == c) return true;
  }
  return name.starts_with("param.");
}

// Words of a metric's name that say it counts something achieved, so more is better.
bool achievement_word(std::string_view w) {
  for (std::string_view a : {"solved", "success", "successes", "reached", "arrived", "clearance", "coverage"}) {
    if (w == a) return true;
  }
  return false;
}

bool identifier_like(std::string_view s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  for (unsigned char c : s) {
    if (!std::isalnum(c) && c != '_' && c != '.' && c != '-') return false;
  }
  return true;
}

}  // namespace

void check_cost_metric(const std::string& name) {
  if (text_column(name)) throw ParameterError("'" + name + "' is not a numeric metric of a run");
  if (!identifier_like(name)) {
    throw ParameterError("'" + name + "' is neither a run-record column nor an extra metric's name");
  }
}

bool solved_only_metric(std::string_view name) { return name == "path_length" || name == "path_clearance"; }

MetricSample metric_sample(const core::RunRecord& r, std::string_view name) {
  using Kind = MetricSample::Kind;
  if (const std::optional<double> v = column(r, name)) {
    if (solved_only_metric(name) && r.status != core::PlanStatus::kSolved) return {Kind::kExcluded, 0.0};
    return {Kind::kValue, *v};
  }
  const auto it = r.extra.find(std::string(name));
  if (it == r.extra.end() || !std::isfinite(it->second)) return {Kind::kMissing, 0.0};
  return {Kind::kValue, it->second};
}

std::string metric_label(std::string_view name) {
  return name == kDefaultCost ? std::string("CD calls") : std::string(name);
}

CostDirection default_cost_direction(std::string_view name) {
  if (name == "path_clearance") return CostDirection::kHigher;
  const core::RunRecord probe;  // column() of any record says whether the name is a column
  if (column(probe, name)) return CostDirection::kLower;  // the other columns count work or length
  std::size_t begin = 0;
  while (begin <= name.size()) {
    std::size_t end = name.find_first_of("_.-", begin);
    if (end == std::string_view::npos) end = name.size();
    if (achievement_word(name.substr(begin, end - begin))) return CostDirection::kHigher;
    begin = end + 1;
  }
  return CostDirection::kLower;
}

std::string_view to_string(CostDirection d) { return d == CostDirection::kHigher ? "higher" : "lower"; }

CostDirection parse_cost_direction(std::string_view word) {
  if (word == "higher") return CostDirection::kHigher;
  if (word == "lower") return CostDirection::kLower;
  throw ParameterError("expected 'higher' or 'lower' (which values of the cost are better), got '" +
                       std::string(word) + "'");
}

}  // namespace amp::bench
