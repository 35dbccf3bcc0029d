#pragma once
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "amp/learn/clusterer.hpp"
#include "amp/roadmap/uas/training_roadmap.hpp"
#include "amp/world/planning_features.hpp"

namespace amp::roadmap {

// A cluster's visibility figures, as the UAS paper's Tables 1-3 print them.
struct ClusterStats {
  std::size_t size = 0;
  double size_percent = 0.0;  // of the training set
  double visibility_mean = 0.0;
  double visibility_std = 0.0;  // sample standard deviation (n - 1), as MATLAB's std; 0 for one node
  double visibility_min = 0.0;
  double visibility_max = 0.0;
};

// A UAS region: the bounding box of one cluster's reference points, grown as RegionSettings says.
struct Region {
  Eigen::AlignedBox3d box;
  std::vector<std::size_t> members;  // training-set indices
  ClusterStats stats;
};

struct RegionSettings {
  std::string clustering = "kmeans";  // kmeans | ward | pgmeans | auto
  TrainingSettings training;
  // Each side of a box may grow by margin x the robot's size. 0 (the paper's plain bounding boxes) by
  // measurement: at 0.5, UAS cost 1.16x Hybrid PRM's median on the Maze (Wilcoxon p = 0.004), and
  // at 0 it was 0.77-0.88x on the Hook and 0.82x on Walls (two seeds, 100 runs each; docs/uas.md).
  double margin = 0.0;
  // clustering, the training fields and region_margin, as uas takes them.
  static const core::SettingsSchema<RegionSettings>& schema();
  void validate() const;  // throws ParameterError (also for an unknown clustering name)
};

// The training set, its clustering and its regions (the UAS region-identification study, Algorithm 2.1 line 1).
struct RegionModel {
  TrainingSet training;
  learn::Clustering clustering;
  std::string method;  // the clustering used (for auto: the one it chose)
  std::vector<std::string> auto_methods;  // auto only: the methods tried, their silhouettes and c
  std::vector<double> auto_scores;
  std::vector<int> auto_clusters;
  std::vector<Region> regions;  // one per cluster, in cluster order
  double robot_size = 0.0;      // the minimum side of a region
  int seed_extensions = 0;      // boxes grown to take in a seed no region covered
};

// Per-cluster statistics of the training nodes' visibility.
std::vector<ClusterStats> cluster_stats(const std::vector<double>& visibility, const std::vector<int>& labels, int c);

// Bounding boxes of the clusters' reference points, grown on every side by margin x robot_size,
// then to at least robot_size per side (a cluster of one node, or of nodes on a line, has zero
// volume), clipped to `bounds`. Planar worlds (planar = true) keep z at [0, 0]. Then every seed
// position outside all boxes is taken into the box of the cluster of its nearest training node.
std::vector<Region> make_regions(const TrainingSet& training, const std::vector<int>& labels, int c,
                                 const Eigen::AlignedBox3d& bounds, double robot_size, double margin,
                                 const std::vector<Eigen::Vector3d>& seed_positions, int* seed_extensions = nullptr);

// A region's weight in UAS's weighted schedule: 1 + its training nodes of visibility below 1/2 (the
// cc-expand threshold), i.e. how much narrow space the training roadmap saw in it.
double narrow_weight(const Region& region, const TrainingSet& training);

// The robot's size for regions: its bounding diameter (2 x robot_radius), or 1% of the workspace
// extent for a point robot.
double region_robot_size(const world::PlanningFeatures& features);

// Training roadmap (CD calls in the counters' current phase), standardised features, clustering and
// regions. If `stop` fires during training or clustering, the model holds the training set (partial,
// if cut short), no clustering and no region (training.stopped says why). Throws amp::Error when
// training found no free state.
RegionModel identify_regions(const PlanningContext& ctx, const RegionSettings& settings,
                             const core::StopCondition& stop, core::Rng& rng);

}  // namespace amp::roadmap
