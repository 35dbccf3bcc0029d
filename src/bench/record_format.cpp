#include "amp/bench/record_format.hpp"

#include <iomanip>
#include <sstream>

#include <nlohmann/json.hpp>

namespace amp::bench {

nlohmann::json to_json(const core::RunRecord& r) {
  nlohmann::json j;
  j["planner"] = r.planner;
  j["problem"] = r.problem;
  j["seed"] = r.seed;
  j["status"] = std::string(core::to_string(r.status));
  if (!r.message.empty()) j["message"] = r.message;
  j["wall_time_s"] = r.wall_time_s;
  j["cd_calls"] = r.cd_calls();
  j["cd_calls_training"] = r.cd_calls_training;
  j["cd_calls_planning"] = r.cd_calls_planning;
  j["cd_calls_query"] = r.cd_calls_query;
  j["clearance_calls"] = r.clearance_calls;
  j["nodes"] = r.nodes;
  j["edges"] = r.edges;
  j["components"] = r.components;
  j["lp_calls"] = r.lp_calls;
  j["lp_successes"] = r.lp_successes;
  j["path_states"] = r.path_states;
  j["path_length"] = r.path_length;
  j["path_clearance"] = r.path_clearance;
  j["extra"] = nlohmann::json::object();
  for (const auto& [k, v] : r.extra) j["extra"][k] = v;
  return j;
}

std::string format_table(const core::RunRecord& r) {
  std::ostringstream out;
  auto row = [&](const std::string& name, const auto& value) {
    out << "  " << std::left << std::setw(22) << name << value << '\n';
  };
  row("planner", r.planner);
  row("problem", r.problem);
  row("seed", r.seed);
  row("status", std::string(core::to_string(r.status)));
  if (!r.message.empty()) row("message", r.message);
  std::ostringstream t;
  t << std::fixed << std::setprecision(4) << r.wall_time_s << " s";
  row("wall time", t.str());
  row("CD calls", r.cd_calls());
  row("  training", r.cd_calls_training);
  row("  planning", r.cd_calls_planning);
  row("  query/smoothing", r.cd_calls_query);
  row("clearance calls", r.clearance_calls);
  row("nodes", r.nodes);
  row("edges", r.edges);
  row("components", r.components);
  std::ostringstream lp;
  lp << r.lp_successes << " / " << r.lp_calls << " succeeded";
  row("local planner", lp.str());
  if (r.status == core::PlanStatus::kSolved) {
    row("path states", r.path_states);
    row("path length", r.path_length);
    row("path clearance", r.path_clearance);
  }
  for (const auto& [k, v] : r.extra) row(k, v);
  return out.str();
}

}  // namespace amp::bench
