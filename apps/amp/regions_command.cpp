// `amp regions`: UAS's region identification alone. Builds the training roadmap, clusters it,
// prints the paper's per-cluster statistics (Tables 1-3) and draws the clusters and boxes.
#include <cstdio>
#include <iostream>
#include <limits>
#include <memory>

#include <nlohmann/json.hpp>

#include "amp/core/counters.hpp"
#include "amp/core/error.hpp"
#include "amp/learn/clusterer_choice.hpp"
#include "amp/roadmap/planner.hpp"
#include "amp/roadmap/uas_regions.hpp"
#include "amp/viz/scene_renderer.hpp"
#include "amp/world/problem.hpp"
#include "cli_util.hpp"
#include "commands.hpp"

namespace amp::cli {

namespace {

struct RegionsOptions {
  std::string problem;
  std::string clustering = "kmeans";
  std::vector<int> training_nodes{200};
  int training_k = 5;
  double margin = 0.5;
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

std::string box_text(const Eigen::AlignedBox3d& b, bool planar) {
  char buf[160];
  if (planar) {
    std::snprintf(buf, sizeof buf, "[%.2f, %.2f] x [%.2f, %.2f]", b.min().x(), b.max().x(), b.min().y(), b.max().y());
  } else {
    std::snprintf(buf, sizeof buf, "[%.2f, %.2f] x [%.2f, %.2f] x [%.2f, %.2f]", b.min().x(), b.max().x(),
                  b.min().y(), b.max().y(), b.min().z(), b.max().z());
  }
  return buf;
}

void print_table(const world::Problem& problem, const roadmap::RegionModel& m, std::uint64_t cd_calls) {
  std::printf("%s: training roadmap %zu nodes, %zu edges, %llu CD calls; %s: %d cluster%s\n", problem.name.c_str(),
              m.training.size(), m.training.roadmap->edge_count(), static_cast<unsigned long long>(cd_calls),
              m.method.c_str(), m.clustering.c, m.clustering.c == 1 ? " (UAS would fall back to global Hybrid PRM)" : "s");
  for (std::size_t i = 0; i < m.auto_methods.size(); ++i) {
    std::printf("  auto: %-8s %2d clusters, mean silhouette %.3f%s\n", m.auto_methods[i].c_str(), m.auto_clusters[i],
                m.auto_scores[i], m.auto_methods[i] == m.method ? "  <- chosen" : "");
  }
  std::printf("  %-7s %8s %8s %8s %8s %8s  %s\n", "cluster", "size(%)", "vis.avg", "vis.std", "vis.min", "vis.max",
              "region box");
  for (std::size_t j = 0; j < m.regions.size(); ++j) {
    const roadmap::ClusterStats& s = m.regions[j].stats;
    std::printf("  %-7zu %8.1f %8.3f %8.3f %8.3f %8.3f  %s\n", j, s.size_percent, s.visibility_mean, s.visibility_std,
                s.visibility_min, s.visibility_max, box_text(m.regions[j].box, m.training.planar).c_str());
  }
}

nlohmann::json to_json(const roadmap::RegionModel& m, std::uint64_t cd_calls) {
  nlohmann::json clusters = nlohmann::json::array();
  for (const roadmap::Region& r : m.regions) {
    clusters.push_back({{"size", r.stats.size},
                        {"size_percent", r.stats.size_percent},
                        {"visibility_mean", r.stats.visibility_mean},
                        {"visibility_std", r.stats.visibility_std},
                        {"visibility_min", r.stats.visibility_min},
                        {"visibility_max", r.stats.visibility_max},
                        {"box_min", {r.box.min().x(), r.box.min().y(), r.box.min().z()}},
                        {"box_max", {r.box.max().x(), r.box.max().y(), r.box.max().z()}}});
  }
  nlohmann::json j{{"training_nodes", m.training.size()},
                   {"training_edges", m.training.roadmap->edge_count()},
                   {"training_cd_calls", cd_calls},
                   {"method", m.method},
                   {"clusters", m.clustering.c},
                   {"regions", clusters}};
  for (std::size_t i = 0; i < m.auto_methods.size(); ++i) {
    j["auto"][m.auto_methods[i]] = {{"clusters", m.auto_clusters[i]}, {"silhouette", m.auto_scores[i]}};
  }
  return j;
}

void draw(const world::Problem& problem, const roadmap::RegionModel& m, const std::string& file) {
  viz::RoadmapDrawing drawing = viz::drawing_of(*m.training.roadmap);
  drawing.labels = m.clustering.labels;
  std::vector<viz::RegionDrawing> regions;
  for (std::size_t j = 0; j < m.regions.size(); ++j) {
    const auto& b = m.regions[j].box;
    char label[96];
    std::snprintf(label, sizeof label, "%zu: %.0f%%, vis %.2f", j, m.regions[j].stats.size_percent,
                  m.regions[j].stats.visibility_mean);
    regions.push_back({Eigen::AlignedBox2d(b.min().head<2>(), b.max().head<2>()), static_cast<int>(j), label});
  }
  viz::SceneOptions scene;
  scene.roadmap = &drawing;
  scene.regions = &regions;
  scene.title = problem.name + " — UAS regions, " + m.method + ", " + std::to_string(m.training.size()) +
                " training nodes";
  viz::write_text_file(file, viz::render_scene(problem, scene));
}

int run_regions(const RegionsOptions& o) {
  learn::make_clusterer(o.clustering);  // an unknown name fails before any work
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
      all.push_back(to_json(model, counters.cd_calls()));
    } else {
      print_table(problem, model, counters.cd_calls());
    }
    if (!o.output.empty()) {
      const auto file = picture_file(o, n);
      draw(problem, model, file.string());
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
  cmd->add_option("--margin", o->margin, "Region box growth per side, in robot sizes [0.5]")->check(CLI::Range(0.0, 100.0));
  cmd->add_option("--seed", o->seed, "Random seed (same regions as amp plan --planner uas --seed) [1]")
      ->check(unsigned_integer());
  cmd->add_option("-o,--output", o->output, "SVG file to draw the clusters and regions to");
  cmd->add_flag("--json", o->json, "Print the statistics as JSON");
  cmd->add_flag("--force", o->force, "Overwrite existing output files");
  cmd->callback([o, &exit_code] { exit_code = run_regions(*o); });
}

}  // namespace amp::cli
