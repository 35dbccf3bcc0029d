#include "amp/learn/clusterer_choice.hpp"

#include <string>

#include "amp/core/error.hpp"
#include "amp/core/rng.hpp"
#include "amp/learn/kmeans.hpp"
#include "amp/learn/pg_means.hpp"
#include "amp/learn/silhouette.hpp"
#include "amp/learn/ward.hpp"

namespace amp::learn {

std::unique_ptr<Clusterer> make_clusterer(std::string_view name) {
  if (name == "kmeans") return std::make_unique<KMeans>();
  if (name == "ward") return std::make_unique<WardClustering>();
  if (name == "pgmeans") return std::make_unique<PgMeans>();
  if (name == "auto") return std::make_unique<AutoClusterer>();
  throw ParameterError("unknown clustering '" + std::string(name) + "' (choose kmeans, ward, pgmeans or auto)");
}

ClusteringChoice AutoClusterer::choose(const Eigen::MatrixXd& points, core::Rng& rng,
                                       const core::StopCondition* stop) const {
  validate_points(points, "auto clustering");
  const std::uint64_t base = rng.next_u64();
  ClusteringChoice out;
  double best = -2.0;
  std::uint64_t stream = 0;
  for (const std::string_view name : {"kmeans", "ward", "pgmeans"}) {
    core::Rng own(core::derive_seed(base, stream++));
    Clustering c = make_clusterer(name)->cluster(points, own, stop);
    const double score = mean_silhouette(points, c.labels, c.c, stop);
    out.methods.emplace_back(name);
    out.scores.push_back(score);
    out.clusters.push_back(c.c);
    if (score > best) {
      best = score;
      out.method = name;
      out.clustering = std::move(c);
    }
  }
  return out;
}

Clustering AutoClusterer::cluster(const Eigen::MatrixXd& points, core::Rng& rng,
                                  const core::StopCondition* stop) const {
  return choose(points, rng, stop).clustering;
}

}  // namespace amp::learn
