// `amp render`: draws a problem, a path file and optionally a roadmap as SVG.
#include <iostream>
#include <memory>
#include <optional>

#include "amp/core/path_file.hpp"
#include "amp/roadmap/run.hpp"
#include "amp/viz/scene_renderer.hpp"
#include "amp/world/problem.hpp"
#include "cli_util.hpp"
#include "commands.hpp"

namespace amp::cli {

namespace {

struct RenderOptions {
  std::string problem;
  std::string path;
  std::string output;
  bool roadmap = false;
  std::string planner;
  std::uint64_t seed = 1;
  int width = 900;
  bool force = false;
};

int run_render(const RenderOptions& o) {
  check_writable(o.output, o.force, "-o");
  const world::Problem problem = world::load_problem(o.problem);
  std::vector<State> path;
  if (!o.path.empty()) path = core::read_path_file(o.path, *problem.space);

  viz::RoadmapDrawing drawing;
  viz::SceneOptions scene;
  scene.width_px = o.width;
  if (o.roadmap) {
    // A roadmap is drawn from a fresh run of the planner with the given seed.
    const std::string planner = resolve_planner(o.planner, problem);
    const roadmap::RunOutcome run =
        roadmap::execute_run(problem, planner, {}, o.seed, problem.defaults.time_limit_s, std::nullopt);
    if (run.roadmap) {
      drawing = viz::drawing_of(*run.roadmap);
      scene.roadmap = &drawing;
    }
    if (path.empty() && run.record.status == core::PlanStatus::kSolved) path = run.path;
    scene.title = problem.name + " — " + planner + " roadmap, seed " + std::to_string(o.seed);
  }
  if (!path.empty()) scene.path = &path;
  viz::write_text_file(o.output, viz::render_scene(problem, scene));
  std::cout << "picture written to " << o.output << '\n';
  return kExitOk;
}

}  // namespace

void add_render_command(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<RenderOptions>();
  CLI::App* cmd = app.add_subcommand("render", "Draw a problem (and a path, a roadmap) as SVG");
  cmd->add_option("problem", o->problem, "Problem file (.yaml or OMPL.app .cfg)")->required();
  cmd->add_option("--path", o->path, "Path file to draw (as written by amp plan --out)");
  cmd->add_flag("--roadmap", o->roadmap, "Plan with --planner/--seed and draw the roadmap");
  cmd->add_option("--planner", o->planner, "Planner for --roadmap (default: the problem's)");
  cmd->add_option("--seed", o->seed, "Seed for --roadmap [1]")->check(unsigned_integer());
  cmd->add_option("--width", o->width, "Image width in pixels [900]")->check(CLI::Range(200, 8000));
  cmd->add_option("-o,--output", o->output, "SVG file to write")->required();
  cmd->add_flag("--force", o->force, "Overwrite an existing output file");
  cmd->callback([o, &exit_code] { exit_code = run_render(*o); });
}

}  // namespace amp::cli
