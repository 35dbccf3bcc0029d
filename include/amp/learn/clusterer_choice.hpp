#pragma once
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "amp/learn/clusterer.hpp"

namespace amp::learn {

// The clustering methods by name: "kmeans", "ward", "pgmeans" (default settings each), and "auto".
inline constexpr std::string_view kClusteringNames[] = {"kmeans", "ward", "pgmeans", "auto"};

// Throws ParameterError naming the valid choices for any other name.
std::unique_ptr<Clusterer> make_clusterer(std::string_view name);

// What "auto" chose and why.
struct ClusteringChoice {
  Clustering clustering;
  std::string method;               // the winning method's name
  std::vector<std::string> methods;  // every method tried, in order
  std::vector<double> scores;        // its mean silhouette
  std::vector<int> clusters;         // its number of clusters
};

// Chooses the clustering per problem (the UAS paper's future work): runs k-means, Ward and PG-means
// on the same points and keeps the one with the highest mean silhouette width (silhouette.hpp), i.e.
// the partition whose clusters are most compact and apart in the standardised features; a method
// that found one cluster scores 0. Ties keep the earlier method (kmeans, ward, pgmeans). Each method
// gets its own Rng stream derived from one draw of `rng`, so the choice does not depend on order.
// The rule is measured against the best fixed method in docs/uas.md.
class AutoClusterer final : public Clusterer {
 public:
  using Clusterer::cluster;
  Clustering cluster(const Eigen::MatrixXd& points, core::Rng& rng, const core::StopCondition* stop) const override;
  std::string_view name() const override { return "auto"; }
  ClusteringChoice choose(const Eigen::MatrixXd& points, core::Rng& rng,
                          const core::StopCondition* stop = nullptr) const;
};

}  // namespace amp::learn
