// `amp plan`: one planner run on one problem; prints the run record, writes the path.
#include <iostream>
#include <memory>
#include <optional>

#include <nlohmann/json.hpp>

#include "amp/bench/record_format.hpp"
#include "amp/core/path_file.hpp"
#include "amp/roadmap/run.hpp"
#include "amp/viz/scene_renderer.hpp"
#include "amp/world/problem.hpp"
#include "cli_util.hpp"
#include "problem_input.hpp"
#include "commands.hpp"

namespace amp::cli {

namespace {

struct PlanOptions {
  std::string problem;
  MapQuery map;                  // with a map_server YAML as the problem
  ArmInput arm;                  // an arm from a MoveIt user's files, instead of a problem file
  const CLI::App* cmd = nullptr;  // to tell which options were given
  std::string planner;
  std::vector<std::string> params;
  std::uint64_t seed = 1;
  double time_limit = 0.0;  // 0: the problem's default
  long long node_limit = 0;
  std::string edge_check;  // empty: the problem's
  std::string out;
  std::string format = "path";
  std::string svg;
  bool roadmap = false;
  bool json = false;
  bool force = false;
};

int run_plan(const PlanOptions& o) {
  const core::PathFormat format = core::path_format_from_string(o.format);
  if (!o.out.empty()) check_writable(o.out, o.force, "--out");
  if (!o.svg.empty()) check_writable(o.svg, o.force, "--svg");
  const auto resolved = [](const std::string& f) {
    return std::filesystem::weakly_canonical(std::filesystem::absolute(f));
  };
  if (!o.out.empty() && !o.svg.empty() && resolved(o.out) == resolved(o.svg)) {
    throw Error("--svg: '" + o.svg + "' is the --out file too; the picture would replace the path");
  }
  if (o.problem.empty() && !o.arm.given()) throw Error("PROBLEM: give a problem file, or --urdf, --srdf, --scene and --request");
  world::Problem problem =
      o.arm.given() ? load_arm_input(o.arm, o.problem) : load_problem_input(o.problem, o.map, true, *o.cmd, &o.arm);
  if (!o.edge_check.empty()) problem.defaults.edge_check = core::parse_edge_check_mode(o.edge_check);
  const std::string planner = resolve_planner(o.planner, problem);
  const double time_limit = o.time_limit > 0.0 ? o.time_limit : problem.defaults.time_limit_s;
  const std::optional<std::size_t> given =
      o.node_limit > 0 ? std::optional<std::size_t>(static_cast<std::size_t>(o.node_limit)) : std::nullopt;
  const std::size_t node_limit =
      roadmap::resolve_node_limit(given, problem, roadmap::builtin_planners().info(planner));

  const roadmap::RunOutcome run =
      roadmap::execute_run(problem, planner, parse_params(o.params), o.seed, time_limit, given);

  if (o.json) {
    std::cout << bench::to_json(run.record).dump(2) << '\n';
  } else {
    std::cout << bench::format_table(run.record);
  }
  const bool solved = run.record.status == core::PlanStatus::kSolved;
  if (solved && !o.out.empty()) {
    viz::write_text_file(o.out, core::format_path(*problem.space, run.path, format));
    if (!o.json) std::cout << "path written to " << o.out << '\n';
  }
  if (!o.svg.empty()) {
    viz::RoadmapDrawing drawing;
    if (o.roadmap && run.roadmap) drawing = viz::drawing_of(*run.roadmap);
    viz::SceneOptions scene;
    scene.path = solved ? &run.path : nullptr;
    scene.roadmap = o.roadmap && run.roadmap ? &drawing : nullptr;
    scene.title = problem.name + " — " + planner + ", seed " + std::to_string(o.seed);
    viz::write_text_file(o.svg, viz::render_scene(problem, scene));
    if (!o.json) std::cout << "picture written to " << o.svg << '\n';
  }
  if (run.record.status == core::PlanStatus::kError) {
    throw Error(planner + " failed: " + run.record.message);
  }
  if (!solved && !problem.unsolvable_because.empty()) {
    std::cerr << "amp: no solution: unsolvable: " << problem.unsolvable_because << '\n';
    return kExitNotSolved;
  }
  if (!solved) {
    std::cerr << "amp: no solution: " << core::to_string(run.record.status) << " (time limit " << time_limit
              << " s, "
              << (node_limit == world::kNoNodeLimit ? std::string("no node limit")
                                                    : "node limit " + std::to_string(node_limit))
              << ")\n";
    return kExitNotSolved;
  }
  return kExitOk;
}

}  // namespace

void add_plan_command(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<PlanOptions>();
  CLI::App* cmd = app.add_subcommand("plan", "Solve one problem with one planner; print the run record");
  add_problem_argument(cmd, o->problem);
  cmd->add_option("--planner", o->planner, "Planner name (default: the problem's, else prm)");
  cmd->add_option("--param", o->params, "Planner parameter name=value (repeatable), e.g. --param k=15");
  cmd->add_option("--seed", o->seed, "Random seed [1]")->check(unsigned_integer());
  cmd->add_option("--time-limit", o->time_limit,
                  "Time limit in seconds (default: the problem's: YAML defaults.time_limit, else 30; "
                  ".cfg: its [solver] or [benchmark] time_limit, as OMPL.app stops)")
      ->check(positive_number());
  cmd->add_option("--node-limit", o->node_limit,
                  "Node limit: roadmap nodes, grid-dp's settled cells (default: YAML defaults.node_limit, "
                  "else the planner's: 20000 for roadmap planners, none for grid-dp, which the map bounds; "
                  ".cfg: none, as OMPL.app)")
      ->check(positive_integer());
  cmd->add_option("--edge-check", o->edge_check,
                  "Edge checks: discrete (at the space's resolution; the solution path is certified before "
                  "it is reported) or certified (every edge certified when added) (default: the problem's "
                  "edge_check, else discrete)")
      ->check(CLI::IsMember({"discrete", "certified"}));
  cmd->add_option("--out", o->out, "Write the path to this file");
  cmd->add_option("--format", o->format, "Path format: path (OMPL.app .path) or yaml [path]")
      ->check(CLI::IsMember({"path", "yaml"}));
  cmd->add_option("--svg", o->svg, "Draw the problem and the path to this SVG file");
  cmd->add_flag("--roadmap", o->roadmap, "With --svg: draw the roadmap too");
  cmd->add_flag("--json", o->json, "Print the run record as JSON");
  cmd->add_flag("--force", o->force, "Overwrite existing output files");
  add_map_query_options(cmd, o->map);
  add_arm_options(cmd, o->arm);
  o->cmd = cmd;
  cmd->callback([o, &exit_code] { exit_code = run_plan(*o); });
}

}  // namespace amp::cli
