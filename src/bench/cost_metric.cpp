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

}  // namespace amp::bench
