// `amp navigate`: a method of the policy-search paper (policy search seeded by a value function, or
// its baseline, the Dynamic Window Approach following the value function) planned and driven on a
// noisy simulated unicycle over many seeds; prints the execution statistics (the paper's Table 2).
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "amp/core/error.hpp"
#include "amp/core/rng.hpp"
#include "amp/nav/navigator_catalog.hpp"
#include "amp/stats/descriptive.hpp"
#include "amp/viz/scene_renderer.hpp"
#include "amp/world/problem.hpp"
#include "cli_util.hpp"
#include "commands.hpp"

namespace amp::cli {

namespace {

struct NavigateOptions {
  std::string problem;
  std::string method = "policy";
  int runs = 50;
  std::uint64_t seed = 1;
  std::vector<std::string> params;
  std::string output;
  bool json = false;
  bool force = false;
};

constexpr double kRunTimeLimitS = 600.0;  // CPU seconds per run; simulated time has its own limit (max_time)

double median(std::vector<double> x) {
  if (x.empty()) return 0.0;
  std::sort(x.begin(), x.end());
  return stats::quantile(x, 0.5);
}

int run_navigate(const NavigateOptions& o) {
  const std::string method = o.method == "policy" ? "policy-search" : "dwa";
  const core::ParamMap params = parse_params(o.params);
  const std::filesystem::path record_file = std::filesystem::path(o.output) / "record.json";
  if (!o.output.empty()) {
    std::error_code ec;
    if (std::filesystem::exists(o.output, ec) && !std::filesystem::is_directory(o.output, ec)) {
      throw Error("-o: '" + o.output + "' is a file, expected a directory");
    }
    if (std::filesystem::exists(o.output, ec)) check_writable(record_file, o.force, "-o");
  }
  const world::Problem problem = world::load_problem(o.problem);
  nlohmann::json runs = nlohmann::json::array();
  std::vector<double> planning, execution, distance;
  double min_clearance = 0.0, collisions = 0.0, waypoints = 0.0;
  int solved = 0;
  for (int i = 0; i < o.runs; ++i) {
    const std::uint64_t seed = core::derive_seed(o.seed, static_cast<std::uint64_t>(i));
    const nav::NavigationOutcome out = nav::execute_navigation(problem, method, params, seed, kRunTimeLimitS);
    const core::RunRecord& r = out.record;
    if (r.status == core::PlanStatus::kError) throw Error(method + ": " + r.message);
    const bool arrived = r.extra.at("arrived") != 0.0;
    solved += arrived ? 1 : 0;
    planning.push_back(out.planning_time_s);
    execution.push_back(r.extra.at("execution_time_s"));
    distance.push_back(r.extra.at("distance"));
    collisions += r.extra.at("collisions");
    min_clearance = i == 0 ? r.extra.at("min_clearance") : std::min(min_clearance, r.extra.at("min_clearance"));
    if (r.extra.contains("waypoints")) waypoints = r.extra.at("waypoints");
    runs.push_back({{"seed", seed},
                    {"arrived", arrived},
                    {"planning_time_s", out.planning_time_s},
                    {"execution_time_s", r.extra.at("execution_time_s")},
                    {"distance", r.extra.at("distance")},
                    {"min_clearance", r.extra.at("min_clearance")},
                    {"collisions", r.extra.at("collisions")},
                    {"speeds", out.speeds}});
  }
  nlohmann::json record = {{"method", method},
                           {"problem", problem.name},
                           {"seed", o.seed},
                           {"runs", o.runs},
                           {"solved_runs", solved},
                           {"collisions_total", collisions},
                           {"planning_time_median_s", median(planning)},
                           {"execution_time_median_s", median(execution)},
                           {"distance_median", median(distance)},
                           {"min_clearance_min", min_clearance},
                           {"waypoints", waypoints}};
  if (o.json) {
    std::cout << record.dump(2) << '\n';
  } else {
    for (const auto& [key, value] : record.items()) std::cout << "  " << key << std::string(26 - std::min<std::size_t>(25, key.size()), ' ') << value.dump() << '\n';
  }
  if (!o.output.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(o.output, ec);
    if (ec) throw FileError(o.output + ": cannot create the directory: " + ec.message());
    nlohmann::json full = record;
    full["params"] = nlohmann::json::object();
    for (const auto& [name, value] : params) full["params"][name] = value.to_string();
    full["run_details"] = runs;
    viz::write_text_file(record_file.string(), full.dump(2) + "\n");
    if (!o.json) std::cout << "written to " << o.output << "/: record.json\n";
  }
  return kExitOk;
}

}  // namespace

void add_navigate_command(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<NavigateOptions>();
  CLI::App* cmd = app.add_subcommand("navigate", "Policy search seeded by a value function, or the Dynamic Window "
                                                 "Approach, driven on a noisy unicycle over many seeds");
  cmd->add_option("problem", o->problem, "Problem file (a map world, disc robot: its start and goal)")->required();
  cmd->add_option("--method", o->method, "policy (policy search) or dwa [policy]")->check(CLI::IsMember({"policy", "dwa"}));
  cmd->add_option("--runs", o->runs, "Noisy runs, one seed each [50]")->check(positive_integer());
  cmd->add_option("--seed", o->seed, "Random seed (each run's noise is drawn from a stream of it) [1]")->check(unsigned_integer());
  cmd->add_option("--param", o->params, "Method parameter name=value (repeatable; `amp bench --list` shows them)");
  cmd->add_option("-o,--output", o->output, "Directory for record.json");
  cmd->add_flag("--json", o->json, "Print the record as one flat JSON object");
  cmd->add_flag("--force", o->force, "Overwrite existing output files");
  cmd->callback([o, &exit_code] { exit_code = run_navigate(*o); });
}

}  // namespace amp::cli
