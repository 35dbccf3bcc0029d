// `amp navigate`: a method of the policy-search paper (policy search seeded by a value function, or
// its baseline, the Dynamic Window Approach following the value function) planned and driven on a
// noisy simulated unicycle over many seeds; prints the execution statistics (the paper's Table 2).
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "amp/core/error.hpp"
#include "amp/nav/navigator_catalog.hpp"
#include "amp/world/problem.hpp"
#include "cli_util.hpp"
#include "problem_input.hpp"
#include "commands.hpp"
#include "amp/study/navigate_study.hpp"

namespace amp::cli {

namespace {

struct NavigateOptions {
  std::string problem;
  MapQuery map;                  // with a map_server YAML as the problem
  const CLI::App* cmd = nullptr;  // to tell which options were given
  std::string method = "policy";
  int runs = 50;
  std::uint64_t seed = 1;
  std::vector<std::string> params;
  std::string output;
  bool json = false;
  bool force = false;
};

int run_navigate(const NavigateOptions& o) {
  const std::string method = o.method == "policy" ? study::kPolicyMethod : study::kDwaMethod;
  study::NavigateSetup setup;
  setup.runs = o.runs;
  setup.seed = o.seed;
  setup.params = parse_params(o.params);
  if (!o.output.empty()) study::check_output_dir(o.output, study::navigate_output_files(), o.force, "-o");
  // A parameter neither method declares is an error, as in `amp bench`.
  try {
    study::route_navigate_params(setup.params);
  } catch (const ParameterError& e) {
    throw ParameterError(std::string("--param: ") + e.what());
  }

  const world::Problem problem = load_problem_input(o.problem, o.map, true, *o.cmd);
  // The other method runs beside the chosen one on the same seeds: Table 2 and Figure 4 compare both.
  const study::NavigateResult r = study::run_both_methods(problem, setup);
  const study::MethodRuns& chosen = method == study::kPolicyMethod ? r.policy : r.dwa;
  if (o.json) {
    std::cout << chosen.record.dump(2) << '\n';
  } else {
    for (const auto& [key, value] : chosen.record.items()) {
      std::cout << "  " << key << std::string(26 - std::min<std::size_t>(25, key.size()), ' ') << value.dump() << '\n';
    }
    std::cout << '\n' << study::format_table2(r, setup);
  }
  if (o.output.empty()) return kExitOk;
  study::write_navigate_outputs(problem, r, method, setup, o.output);
  if (!o.json) std::cout << "written to " << o.output << "/: record.json, phases.svg, velocity.svg\n";
  return kExitOk;
}

}  // namespace

void add_navigate_command(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<NavigateOptions>();
  CLI::App* cmd = app.add_subcommand("navigate", "Policy search seeded by a value function, or the Dynamic Window "
                                                 "Approach, driven on a noisy unicycle over many seeds");
  cmd->add_option("problem", o->problem, "Problem file (a map world, disc robot: its start and goal), or a ROS map_server YAML with --start and --goal")->required();
  cmd->add_option("--method", o->method, "policy (policy search) or dwa [policy]")->check(CLI::IsMember({"policy", "dwa"}));
  cmd->add_option("--runs", o->runs, "Noisy runs, one seed each [50]")->check(positive_integer());
  cmd->add_option("--seed", o->seed, "Random seed (each run's noise is drawn from a stream of it) [1]")->check(unsigned_integer());
  cmd->add_option("--param", o->params, "Method parameter name=value (repeatable; `amp bench --list` shows them)");
  cmd->add_option("-o,--output", o->output, "Directory for record.json, phases.svg (Figure 3) and velocity.svg (Figure 4)");
  cmd->add_flag("--json", o->json, "Print the record as one flat JSON object");
  cmd->add_flag("--force", o->force, "Overwrite existing output files");
  add_map_query_options(cmd, o->map);
  o->cmd = cmd;
  cmd->callback([o, &exit_code] { exit_code = run_navigate(*o); });
}

}  // namespace amp::cli
