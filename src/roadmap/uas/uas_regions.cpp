#include "amp/roadmap/uas/uas_regions.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "amp/core/error.hpp"
#include "amp/learn/clusterer_choice.hpp"
#include "amp/learn/standardize.hpp"
#include "amp/roadmap/prm/node_classifier.hpp"
#include "amp/world/environment.hpp"

namespace amp::roadmap {

namespace {
constexpr double kPointRobotExtentFraction = 0.01;
}  // namespace

const core::SettingsSchema<RegionSettings>& RegionSettings::schema() {
  using S = RegionSettings;
  static const core::SettingsSchema<S> schema("uas", [] {
    std::vector<core::SettingsField<S>> f;
    f.push_back(core::choice_field<S>("clustering", &S::clustering,
                                      std::vector<std::string>(std::begin(learn::kClusteringNames),
                                                               std::end(learn::kClusteringNames)),
                                      "region identification: kmeans, ward, pgmeans, or auto (highest silhouette)"));
    for (auto& t : core::nested_fields<S>(TrainingSettings::schema(), &S::training)) f.push_back(std::move(t));
    f.push_back(core::real_field<S>("region_margin", &S::margin, 0, 100, "box growth per side, in robot sizes"));
    return f;
  }());
  return schema;
}

void RegionSettings::validate() const {
  schema().validate(*this);
  training.validate();
}

std::vector<ClusterStats> cluster_stats(const std::vector<double>& visibility, const std::vector<int>& labels, int c) {
  std::vector<ClusterStats> out(static_cast<std::size_t>(std::max(c, 0)));
  for (auto& s : out) {
    s.visibility_min = std::numeric_limits<double>::infinity();
    s.visibility_max = -std::numeric_limits<double>::infinity();
  }
  for (std::size_t i = 0; i < labels.size(); ++i) {
    ClusterStats& s = out[static_cast<std::size_t>(labels[i])];
    ++s.size;
    s.visibility_mean += visibility[i];
    s.visibility_min = std::min(s.visibility_min, visibility[i]);
    s.visibility_max = std::max(s.visibility_max, visibility[i]);
  }
  for (auto& s : out) {
    if (s.size == 0) {
      s.visibility_min = s.visibility_max = 0.0;
      continue;
    }
    s.visibility_mean /= static_cast<double>(s.size);
    s.size_percent = 100.0 * static_cast<double>(s.size) / static_cast<double>(labels.size());
  }
  for (std::size_t i = 0; i < labels.size(); ++i) {
    ClusterStats& s = out[static_cast<std::size_t>(labels[i])];
    const double d = visibility[i] - s.visibility_mean;
    s.visibility_std += d * d;
  }
  for (auto& s : out) {
    s.visibility_std = s.size > 1 ? std::sqrt(s.visibility_std / static_cast<double>(s.size - 1)) : 0.0;
  }
  return out;
}

std::vector<Region> make_regions(const TrainingSet& training, const std::vector<int>& labels, int c,
                                 const Eigen::AlignedBox3d& bounds, double robot_size, double margin,
                                 const std::vector<Eigen::Vector3d>& seed_positions, int* seed_extensions) {
  std::vector<Region> regions(static_cast<std::size_t>(c));
  for (std::size_t i = 0; i < labels.size(); ++i) {
    Region& r = regions[static_cast<std::size_t>(labels[i])];
    r.box.extend(training.positions[i]);
    r.members.push_back(i);
  }
  const auto stats = cluster_stats(training.visibility, labels, c);
  const int dims = training.planar ? 2 : 3;
  auto finish = [&](Eigen::AlignedBox3d& box) {
    for (int a = 0; a < dims; ++a) {
      box.min()[a] -= margin * robot_size;
      box.max()[a] += margin * robot_size;
      const double short_by = robot_size - (box.max()[a] - box.min()[a]);
      if (short_by > 0.0) {
        box.min()[a] -= short_by / 2;
        box.max()[a] += short_by / 2;
      }
      box.min()[a] = std::max(box.min()[a], bounds.min()[a]);
      box.max()[a] = std::min(box.max()[a], bounds.max()[a]);
    }
    if (training.planar) box.min().z() = box.max().z() = 0.0;
  };
  for (std::size_t j = 0; j < regions.size(); ++j) {
    regions[j].stats = stats[j];
    finish(regions[j].box);
  }
  int extensions = 0;
  for (Eigen::Vector3d p : seed_positions) {
    if (training.planar) p.z() = 0.0;
    const bool covered = std::any_of(regions.begin(), regions.end(), [&](const Region& r) { return r.box.contains(p); });
    if (covered || training.size() == 0) continue;
    std::size_t nearest = 0;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < training.size(); ++i) {
      const double d = (training.positions[i] - p).head(dims).squaredNorm();
      if (d < best) best = d, nearest = i;
    }
    Eigen::AlignedBox3d& box = regions[static_cast<std::size_t>(labels[nearest])].box;
    box.extend(p);
    finish(box);  // the seed is inside bounds (check_seeds), so the clip keeps it
    ++extensions;
  }
  if (seed_extensions) *seed_extensions = extensions;
  return regions;
}

double narrow_weight(const Region& region, const TrainingSet& training) {
  double narrow = 0.0;
  for (const std::size_t i : region.members) narrow += training.visibility[i] < kExpandVisibility ? 1.0 : 0.0;
  return 1.0 + narrow;
}

double region_robot_size(const world::PlanningFeatures& features) {
  const double d = 2.0 * features.robot_radius();
  if (d > 0.0) return d;
  const Eigen::Vector3d extent = features.workspace_bounds().sizes();
  return kPointRobotExtentFraction * std::max({extent.x(), extent.y(), extent.z()});
}

RegionModel identify_regions(const PlanningContext& ctx, const RegionSettings& settings,
                             const core::StopCondition& stop, core::Rng& rng) {
  settings.validate();
  RegionModel model;
  model.training = build_training_roadmap(ctx, settings.training, stop, rng);
  if (model.training.stopped != core::StopReason::kNone) return model;
  const Eigen::MatrixXd features = learn::standardize(model.training.features());
  try {
    if (settings.clustering == "auto") {
      learn::ClusteringChoice choice = learn::AutoClusterer().choose(features, rng, &stop);
      model.clustering = std::move(choice.clustering);
      model.method = choice.method;
      model.auto_methods = std::move(choice.methods);
      model.auto_scores = std::move(choice.scores);
      model.auto_clusters = std::move(choice.clusters);
    } else {
      model.clustering = learn::make_clusterer(settings.clustering)->cluster(features, rng, &stop);
      model.method = settings.clustering;
    }
  } catch (const learn::ClusteringStopped&) {
    model.training.stopped = stop.check(model.training.size());  // the time limit or a cancel
    return model;
  }
  model.robot_size = region_robot_size(ctx.environment);
  std::vector<Eigen::Vector3d> seeds;
  for (const State& s : ctx.seeds) seeds.push_back(ctx.environment.reference_point(s));
  model.regions = make_regions(model.training, model.clustering.labels, model.clustering.c,
                               ctx.environment.workspace_bounds(), model.robot_size, settings.margin, seeds,
                               &model.seed_extensions);
  return model;
}

}  // namespace amp::roadmap
