// `amp regions`: UAS's region identification alone. Builds the training roadmap, clusters it,
// prints the paper's per-cluster statistics (Tables 1-3) and draws the clusters and boxes.
#include <cstdio>
#include <iostream>
#include <limits>
#include <memory>

#include <nlohmann/json.hpp>

#include "amp/core/counters.hpp"
#include "amp/core/error.hpp"
#include "amp/roadmap/planner.hpp"
#include "amp/roadmap/uas/uas_regions.hpp"
#include "amp/viz/scene_renderer.hpp"
#include "amp/world/problem.hpp"
#include "cli_util.hpp"
#include "region_output.hpp"
#include "commands.hpp"

namespace amp::cli {

namespace {

struct RegionsOptions {
  std::string problem;
  std::string clustering = "kmeans";
  std::vector<int> training_nodes{200};
  int training_k = 5;
  double margin = 0.0;
  std::uint64_t seed = 1;
  std::string output;
  bool json = false;
  bool force = false;
};

// FILE.svg for one training size; with several sizes, FILE-<n>.svg each.
std::filesystem::path picture_file(const RegionsOptions& o, int nodes) {
  std::filesystem::path p(o.output);
  if (o.training_nodes.size() == 1) return p;
  return p.parent_path() / (p.stem().string() + "-" + std::to_string(nodes) + p.extension().string());
}

int run_regions(const RegionsOptions& o) {
  if (!o.output.empty()) {
    for (const int n : o.training_nodes) check_writable(picture_file(o, n), o.force, "-o");
  }
  const world::Problem problem = world::load_problem(o.problem);
  nlohmann::json all = nlohmann::json::array();
  for (const int n : o.training_nodes) {
    roadmap::RegionSettings settings;
    settings.clustering = o.clustering;
    settings.training.nodes = n;
    settings.training.k = o.training_k;
    settings.margin = o.margin;
    settings.validate();
    core::Counters counters;
    const auto checker = problem.environment->make_checker(counters);
    const roadmap::PlanningContext ctx{*problem.space, *problem.environment, *checker, problem.seeds};
    roadmap::check_seeds(ctx);
    // The same Rng stream as `amp plan --planner uas --seed S`, whose regions these are.
    core::Rng rng(o.seed);
    const core::StopCondition stop(problem.defaults.time_limit_s, std::numeric_limits<std::size_t>::max());
    const roadmap::RegionModel model = roadmap::identify_regions(ctx, settings, stop, rng);
    if (model.training.stopped != core::StopReason::kNone) {
      throw Error("the training roadmap hit the problem's time limit (" +
                  std::to_string(problem.defaults.time_limit_s) + " s) after " +
                  std::to_string(model.training.size()) + " nodes");
    }
    if (o.json) {
      all.push_back(region_json(model, counters.cd_calls()));
    } else {
      print_region_table(problem, model, counters.cd_calls());
    }
    if (!o.output.empty()) {
      const auto file = picture_file(o, n);
      draw_regions(problem, model, file.string());
      if (!o.json) std::cout << "picture written to " << file.string() << '\n';
    }
  }
  if (o.json) std::cout << (all.size() == 1 ? all[0] : all).dump(2) << '\n';
  return kExitOk;
}

}  // namespace

void add_regions_command(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<RegionsOptions>();
  CLI::App* cmd = app.add_subcommand("regions", "UAS region identification: cluster a training roadmap, "
                                                "print per-cluster statistics, draw the regions");
  cmd->add_option("problem", o->problem, "Problem file (.yaml or OMPL.app .cfg)")->required();
  cmd->add_option("--clustering", o->clustering, "kmeans, ward, pgmeans or auto [kmeans]")
      ->check(CLI::IsMember({"kmeans", "ward", "pgmeans", "auto"}));
  cmd->add_option("--training-nodes", o->training_nodes,
                  "Training roadmap size; several sizes give one table (and picture) each [200]")
      ->check(CLI::Range(2, 100000));
  cmd->add_option("--training-k", o->training_k, "Neighbours per training node [5]")->check(CLI::Range(1, 1000));
  cmd->add_option("--margin", o->margin, "Region box growth per side, in robot sizes [0]")->check(CLI::Range(0.0, 100.0));
  cmd->add_option("--seed", o->seed, "Random seed (same regions as amp plan --planner uas --seed) [1]")
      ->check(unsigned_integer());
  cmd->add_option("-o,--output", o->output, "SVG file to draw the clusters and regions to");
  cmd->add_flag("--json", o->json, "Print the statistics as JSON");
  cmd->add_flag("--force", o->force, "Overwrite existing output files");
  cmd->callback([o, &exit_code] { exit_code = run_regions(*o); });
}

}  // namespace amp::cli
