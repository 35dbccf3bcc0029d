// `amp demo`: the README's main job. Plans every bundled problem and draws the results, then runs
// the reduced experiments of each capability (benchmark report, UAS, PRM-C/G/L, PGCS exploration,
// policy search, SINS).
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>

#include "amp/bench/bench_runner.hpp"
#include "amp/bench/experiment.hpp"
#include "amp/core/path_file.hpp"
#include "amp/roadmap/run.hpp"
#include "amp/roadmap/uas/uas_regions.hpp"
#include "amp/viz/scene_renderer.hpp"
#include "amp/viz/viewer_page.hpp"
#include "amp/world/problem.hpp"
#include "cli_util.hpp"
#include "amp/study/explore_study.hpp"
#include "amp/study/navigate_study.hpp"
#include "region_output.hpp"
#include "commands.hpp"

namespace amp::cli {

namespace {

// The bundled problems of the foundation, in the order the README lists them.
constexpr const char* kDemoProblems[] = {
    "maze.yaml",  "l-tunnel.yaml", "hook.yaml",        "walls.yaml",          "linkage.yaml",
    "maze3d.yaml", "walls3d.yaml", "office-map.yaml", "movingai-rooms.yaml", "scara-wicket.yaml",
    "puzzle.yaml", "panda-box.yaml",
};

constexpr std::size_t kMaxDrawnRoadmapNodes = 2000;
// PGCS on the office map, reduced to about a second: 5,000 steps cover only the start's room and
// the corridor (coverage 0.4, no query solved); 20,000 reach most rooms (coverage 0.8).
// The novelty walk over 100,000 steps covers most of the office (docs/pgcs.md: 99.6-100% of queries
// solved from 100,000 steps, 1-2 s a run); 20,000 random-walk steps covered 70% and solved 1 of 3.
constexpr long kDemoExploreSteps = 100000;
constexpr const char* kDemoExploration = "novelty";
constexpr int kDemoExploreQueries = 3;
constexpr int kDemoNavigateRuns = 10;  // per method, out of the lab (about a second each)

struct DemoOptions {
  std::string out = "out/demo";
  std::uint64_t seed = 1;
  double time_limit = 60.0;
  int bench_runs = 20;
};

// Runs one of the bundled experiments into `out_dir` (remade: the demo's own directory), with
// `runs` per planner (0: the file's).
void run_demo_bench(const std::filesystem::path& file, const std::filesystem::path& out_dir, int runs) {
  bench::Experiment e = bench::load_experiment(file);
  if (runs > 0) e.runs = runs;
  e.fingerprint = bench::experiment_fingerprint(e);
  bench::BenchOptions b;
  b.out_dir = out_dir;
  b.force = true;
  std::printf("\nBenchmark: %s, %zu problems x %zu planners x %d runs on all cores...\n", e.name.c_str(),
              e.problems.size(), e.planners.size(), e.runs);
  const bench::BenchResult r = bench::run_experiment(e, b);
  std::printf("%zu runs in %.1f s: %s/report.html (and runs.csv, summary.json, results.db)\n", r.written,
              r.wall_time_s, b.out_dir.string().c_str());
}

// `amp explore` reduced: the office explored by PGCS from its start, then a few queries.
void run_demo_explore(const std::filesystem::path& file, const std::filesystem::path& out_dir, std::uint64_t seed) {
  const world::Problem office = world::load_problem(file);
  study::ExploreSetup setup;
  setup.run.steps = kDemoExploreSteps;
  setup.run.queries = kDemoExploreQueries;
  setup.run.exploration = kDemoExploration;
  setup.seed = seed;
  std::printf("\nPGCS exploration of the office map (%s walk, %ld steps, %d queries, seed %llu):\n", kDemoExploration,
              kDemoExploreSteps, kDemoExploreQueries, static_cast<unsigned long long>(seed));
  std::printf("The robot explores, PGCS learns clusters and their Delaunay graph; each query then drives between two\n"
              "random places along graph routes, replanning when an edge proves blocked (solved: it arrived).\n");
  const study::ExploreResult r = study::run_exploration(office, setup);
  std::printf("%s", study::format_explore_table(r.record).c_str());
  study::write_explore_outputs(office, r, out_dir);
  std::printf("pictures: %s/figure1.svg, curves.svg, queries.svg (and record.json)\n", out_dir.string().c_str());
}

// `amp navigate` reduced: policy search and DWA out of the paper's lab, a few noisy runs each.
void run_demo_navigate(const std::filesystem::path& file, const std::filesystem::path& out_dir, std::uint64_t seed) {
  const world::Problem lab = world::load_problem(file);
  study::NavigateSetup setup;
  setup.runs = kDemoNavigateRuns;
  setup.seed = seed;
  std::printf("\nPolicy search against DWA out of the paper's lab (54 cm robot, 60 cm door):\n");
  const study::NavigateResult r = study::run_both_methods(lab, setup);
  std::printf("%s", study::format_table2(r, setup).c_str());
  study::write_navigate_outputs(lab, r, study::kPolicyMethod, setup, out_dir);
  std::printf("pictures: %s/phases.svg, velocity.svg (and record.json)\n", out_dir.string().c_str());
}

int run_demo(const DemoOptions& o) {
  const std::filesystem::path out = o.out;
  std::error_code ec;
  if (std::filesystem::exists(out, ec) && !std::filesystem::is_directory(out, ec)) {
    throw Error("--out: '" + out.string() + "' is a file, expected a directory");
  }
  std::filesystem::create_directories(out, ec);
  if (ec) throw Error("--out: cannot create directory '" + out.string() + "': " + ec.message());
  const std::filesystem::path dir = problems_dir();

  std::printf("AMP demo: PRM on the bundled problems (seed %llu); pictures and paths go to %s/\n\n",
              static_cast<unsigned long long>(o.seed), out.string().c_str());
  std::printf("%-16s %-8s %-10s %10s %11s %8s %12s\n", "problem", "space", "status", "time [s]", "CD calls",
              "nodes", "path length");
  int failures = 0;
  for (const char* name : kDemoProblems) {
    const world::Problem problem = world::load_problem(dir / name);
    const roadmap::RunOutcome run = roadmap::execute_run(problem, problem.defaults.planner, {}, o.seed,
                                                         std::min(o.time_limit, problem.defaults.time_limit_s),
                                                         std::nullopt);
    const auto& r = run.record;
    const bool solved = r.status == core::PlanStatus::kSolved;
    failures += solved ? 0 : 1;
    std::printf("%-16s %-8s %-10s %10.3f %11llu %8llu %12.2f\n", problem.name.c_str(),
                std::string(problem.space->kind()).c_str(), std::string(core::to_string(r.status)).c_str(),
                r.wall_time_s, static_cast<unsigned long long>(r.cd_calls()),
                static_cast<unsigned long long>(r.nodes), r.path_length);
    const std::string stem = std::filesystem::path(name).stem().string();
    viz::RoadmapDrawing drawing;
    viz::SceneOptions scene;
    scene.title = problem.name + " — " + problem.defaults.planner + ", seed " + std::to_string(o.seed);
    if (solved) {
      scene.path = &run.path;
      viz::write_text_file((out / (stem + ".path")).string(), core::format_path(*problem.space, run.path,
                                                                               core::PathFormat::kText));
    }
    // Roadmaps are drawn only while they stay readable (and the SVG small enough to open quickly).
    if (run.roadmap && problem.environment->workspace_dimension() == 2 &&
        run.roadmap->vertex_count() <= kMaxDrawnRoadmapNodes) {
      drawing = viz::drawing_of(*run.roadmap);
      scene.roadmap = &drawing;
    }
    viz::write_text_file((out / (stem + ".svg")).string(), viz::render_scene(problem, scene));
    // A 3-D problem seen from above says little: its page shows it in 3-D, the robot playing the path.
    if (problem.environment->workspace_dimension() == 3) {
      const viz::ViewerContent content = viz::path_content(
          problem, solved ? run.path : std::vector<State>{}, problem.defaults.planner + ", seed " + std::to_string(o.seed));
      viz::write_text_file((out / (stem + ".html")).string(), viz::viewer_page(problem, content));
    }
  }
  std::printf("\n%d of %zu problems solved; open %s/*.svg in a browser (3-D problems: %s/*.html).\n",
              static_cast<int>(std::size(kDemoProblems)) - failures, std::size(kDemoProblems), out.string().c_str(),
              out.string().c_str());

  // The benchmark harness on a reduced experiment: run-cost statistics, database and report.
  run_demo_bench(dir / "experiments" / "quick.yaml", out / "bench", o.bench_runs);

  // UAS: the Maze's regions (the paper's Figure 1 and Table 1), then a reduced Table 4.
  std::printf("\nUAS region identification on the Maze (k-means, 200 training nodes, seed %llu):\n",
              static_cast<unsigned long long>(o.seed));
  const world::Problem maze = world::load_problem(dir / "maze.yaml");
  core::Counters counters;
  const auto checker = maze.environment->make_checker(counters);
  const roadmap::PlanningContext ctx{*maze.space, *maze.environment, *checker, maze.seeds};
  core::Rng rng(o.seed);
  const core::StopCondition stop(o.time_limit, std::numeric_limits<std::size_t>::max());
  const roadmap::RegionModel model = roadmap::identify_regions(ctx, roadmap::RegionSettings{}, stop, rng);
  if (model.training.stopped == core::StopReason::kNone) {
    print_region_table(maze, model, counters.cd_calls());
    std::filesystem::create_directories(out / "uas");
    draw_regions(maze, model, (out / "uas" / "maze-regions.svg").string());
    std::printf("picture: %s\n", (out / "uas" / "maze-regions.svg").string().c_str());
  }
  run_demo_bench(dir / "experiments" / "uas-quick.yaml", out / "uas", 0);

  // PRM-C/G/L: a reduced Table 1 of the run-cost variance paper (the A* grid local planner whose
  // competence is static, global or local; metaplanner draws of o, s, n).
  std::printf("\nRun-cost variance: PRM-C, PRM-G, PRM-L on the SCARA wicket and the puzzle (Table 1, reduced)\n");
  run_demo_bench(dir / "experiments" / "run-cost-variance-quick.yaml", out / "run-cost-variance", 0);

  run_demo_explore(dir / "office-map.yaml", out / "explore", o.seed);
  run_demo_navigate(dir / "policy-lab.yaml", out / "navigate", o.seed);

  // SINS: a reduced first experiment set (the static, random and adaptive systems, each run a
  // sequence of clutter worlds).
  std::printf("\nSINS: the static, random and adaptive systems over clutter worlds (set 1, reduced)\n");
  run_demo_bench(dir / "experiments" / "sins-quick.yaml", out / "sins", 0);
  return failures == 0 ? kExitOk : kExitNotSolved;
}

}  // namespace

void add_demo_command(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<DemoOptions>();
  CLI::App* cmd = app.add_subcommand("demo", "Run the demonstration: plan every bundled problem, draw the results");
  cmd->add_option("--out", o->out, "Output directory [out/demo]");
  cmd->add_option("--seed", o->seed, "Random seed [1]")->check(unsigned_integer());
  cmd->add_option("--time-limit", o->time_limit, "Time limit per problem in seconds [60]")->check(positive_number());
  cmd->add_option("--bench-runs", o->bench_runs, "Runs per planner in the demo benchmark [20]")
      ->check(positive_integer());
  cmd->callback([o, &exit_code] { exit_code = run_demo(*o); });
}

}  // namespace amp::cli
