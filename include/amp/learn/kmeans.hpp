#pragma once
#include <cstddef>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "amp/core/rng.hpp"
#include "amp/learn/clusterer.hpp"

namespace amp::learn {

// One k-means solution for a fixed k.
struct KMeansFit {
  std::vector<int> labels;  // nearest centre of each point (ties: the lower index)
  Eigen::MatrixXd centres;  // k x d
  double wcss = 0.0;        // within-cluster sum of squares
  int iterations = 0;       // assignment passes run
};

// Lloyd's algorithm (Lloyd 1982) from the given k x d centres: assign each point to its nearest
// centre, move each centre to the mean of its points, until no assignment changes or max_iterations.
// A centre left without points jumps to the point farthest from its own centre (so k stays k).
KMeansFit lloyd(const Eigen::MatrixXd& points, Eigen::MatrixXd centres, int max_iterations,
                const core::StopCondition* stop = nullptr);

// k-means++ seeding (Arthur & Vassilvitskii 2007): the first centre is a uniformly random point, each
// next one a point drawn with probability proportional to its squared distance D^2 to the nearest
// centre chosen so far. Returns k x d.
Eigen::MatrixXd kmeans_pp_seeds(const Eigen::MatrixXd& points, int k, core::Rng& rng,
                                const core::StopCondition* stop = nullptr);

// The index i with prefix(i-1) <= u * sum(weights) < prefix(i) (inverse-cdf draw; u in [0, 1)).
// Zero-weight entries are never drawn while some weight is positive; all zero: uniform on u.
std::size_t draw_by_weight(std::span<const double> weights, double u);

// The best of `restarts` k-means++ + Lloyd runs (lowest within-cluster sum of squares; ties keep
// the earlier run).
KMeansFit fit_kmeans(const Eigen::MatrixXd& points, int k, int restarts, int max_iterations, core::Rng& rng,
                     const core::StopCondition* stop = nullptr);

struct KMeansSettings {
  int max_clusters = 10;    // c tried: 1..max_clusters (at most n)
  int restarts = 10;        // seedings per c, best kept
  int max_iterations = 100; // Lloyd passes per run
  void validate() const;    // throws ParameterError
};

// k-means with c chosen by the elbow criterion (elbow.hpp) on f(c) = W(c)/T, W(c) the wcss of the
// best fit for c (the UAS region-identification study, section 2.1.4).
class KMeans final : public Clusterer {
 public:
  explicit KMeans(KMeansSettings settings = {});
  using Clusterer::cluster;
  Clustering cluster(const Eigen::MatrixXd& points, core::Rng& rng, const core::StopCondition* stop) const override;
  std::string_view name() const override { return "kmeans"; }

 private:
  KMeansSettings settings_;
};

}  // namespace amp::learn
