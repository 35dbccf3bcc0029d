// Printing and drawing UAS region models (amp regions, amp demo).
#include "region_output.hpp"

#include <cstdio>

#include "amp/viz/scene_renderer.hpp"
#include "amp/world/problem.hpp"

namespace amp::cli {

namespace {
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

}  // namespace

void print_region_table(const world::Problem& problem, const roadmap::RegionModel& m, std::uint64_t cd_calls) {
  std::printf("%s: training roadmap %zu nodes, %zu edges, %llu CD calls; %s: %d cluster%s\n", problem.name.c_str(),
              m.training.size(), m.training.roadmap->edge_count(), static_cast<unsigned long long>(cd_calls),
              m.method.c_str(), m.clustering.c, m.clustering.c == 1 ? " (UAS would fall back to global Hybrid PRM)" : "s");
  for (std::size_t i = 0; i < m.auto_methods.size(); ++i) {
    std::printf("  auto: %-8s %2d clusters, mean silhouette %.3f%s\n", m.auto_methods[i].c_str(), m.auto_clusters[i],
                m.auto_scores[i], m.auto_methods[i] == m.method ? "  <- chosen" : "");
  }
  std::printf("  %-7s %8s %8s %8s %8s %8s %7s  %s\n", "cluster", "size(%)", "vis.avg", "vis.std", "vis.min", "vis.max",
              "weight", "region box");
  for (std::size_t j = 0; j < m.regions.size(); ++j) {
    const roadmap::ClusterStats& s = m.regions[j].stats;
    std::printf("  %-7zu %8.1f %8.3f %8.3f %8.3f %8.3f %7.0f  %s\n", j, s.size_percent, s.visibility_mean,
                s.visibility_std, s.visibility_min, s.visibility_max, roadmap::narrow_weight(m.regions[j], m.training),
                box_text(m.regions[j].box, m.training.planar).c_str());
  }
  std::printf("  (weight: 1 + training nodes of visibility < 0.5, the region's share of UAS's rounds)\n");
}

nlohmann::json region_json(const roadmap::RegionModel& m, std::uint64_t cd_calls) {
  nlohmann::json clusters = nlohmann::json::array();
  for (const roadmap::Region& r : m.regions) {
    clusters.push_back({{"size", r.stats.size},
                        {"size_percent", r.stats.size_percent},
                        {"visibility_mean", r.stats.visibility_mean},
                        {"visibility_std", r.stats.visibility_std},
                        {"visibility_min", r.stats.visibility_min},
                        {"visibility_max", r.stats.visibility_max},
                        {"weight", roadmap::narrow_weight(r, m.training)},
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

void draw_regions(const world::Problem& problem, const roadmap::RegionModel& m, const std::string& file) {
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

}  // namespace amp::cli
