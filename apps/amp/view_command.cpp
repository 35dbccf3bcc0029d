// `amp view`: a problem, a path and optionally a roadmap as an interactive 3-D page (docs/viewer.md).
// It takes its problem as `amp plan` does, so that what was planned can be looked at.
#include <iostream>
#include <memory>
#include <optional>

#include "amp/core/path_file.hpp"
#include "amp/roadmap/run.hpp"
#include "amp/viz/viewer_page.hpp"
#include "amp/world/problem.hpp"
#include "cli_util.hpp"
#include "commands.hpp"
#include "problem_input.hpp"

namespace amp::cli {

namespace {

struct ViewOptions {
  std::string problem;
  std::string path;
  std::string output;
  bool roadmap = false;
  std::string planner;
  std::uint64_t seed = 1;
  double max_mb = 20.0;
  bool force = false;
  MapQuery map;
  ArmInput arm;
  const CLI::App* cmd = nullptr;
};

int run_view(const ViewOptions& o) {
  check_writable(o.output, o.force, "-o");
  if (o.problem.empty() && !o.arm.given()) throw Error("PROBLEM: give a problem file, or --urdf, --srdf, --scene and --request");
  const world::Problem problem =
      o.arm.given() ? load_arm_input(o.arm, o.problem) : load_problem_input(o.problem, o.map, true, *o.cmd, &o.arm);
  std::vector<State> path;
  std::string source;
  if (!o.path.empty()) {
    path = core::read_path_file(o.path, *problem.space);
    source = "path from " + o.path;
  }
  std::optional<viz::RoadmapDrawing> drawing;
  if (o.roadmap) {
    // As `amp render --roadmap`: a fresh run of the planner with the given seed.
    const std::string planner = resolve_planner(o.planner, problem);
    const roadmap::RunOutcome run =
        roadmap::execute_run(problem, planner, {}, o.seed, problem.defaults.time_limit_s, std::nullopt);
    if (run.roadmap) drawing = viz::drawing_of(*run.roadmap);
    const bool plays_run = path.empty() && run.record.status == core::PlanStatus::kSolved;
    if (plays_run) path = run.path;
    source += (source.empty() ? "" : "; ") + planner + (plays_run ? " path and roadmap" : " roadmap") + ", seed " +
              std::to_string(o.seed);
  }
  viz::ViewerContent content = viz::path_content(problem, path, source);
  content.roadmap = drawing ? &*drawing : nullptr;
  content.max_bytes = static_cast<std::size_t>(o.max_mb * 1e6);
  viz::write_text_file(o.output, viz::viewer_page(problem, content));
  std::cout << "viewer page written to " << o.output << '\n';
  if (!path.empty() && !content.path_certified) std::cout << "warning: " << content.path_failure << '\n';
  return kExitOk;
}

}  // namespace

void add_view_command(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<ViewOptions>();
  CLI::App* cmd = app.add_subcommand("view", "Write an interactive 3-D page of a problem and a path (HTML)");
  add_problem_argument(cmd, o->problem);
  cmd->add_option("--path", o->path, "Path file to play (as written by amp plan --out)");
  cmd->add_flag("--roadmap", o->roadmap, "Plan with --planner/--seed and draw the roadmap (and its path)");
  cmd->add_option("--planner", o->planner, "Planner for --roadmap (default: the problem's)");
  cmd->add_option("--seed", o->seed, "Seed for --roadmap [1]")->check(unsigned_integer());
  cmd->add_option("--max-mb", o->max_mb, "Simplify meshes beyond this page size, in MB [20]")
      ->check(CLI::Range(1.0, 2000.0));
  cmd->add_option("-o,--output", o->output, "HTML file to write")->required();
  cmd->add_flag("--force", o->force, "Overwrite an existing output file");
  add_map_query_options(cmd, o->map);
  add_arm_options(cmd, o->arm);
  o->cmd = cmd;
  cmd->callback([o, &exit_code] { exit_code = run_view(*o); });
}

}  // namespace amp::cli
