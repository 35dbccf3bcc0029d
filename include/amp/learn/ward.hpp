#pragma once
#include <vector>

#include <Eigen/Core>

#include "amp/learn/clusterer.hpp"

namespace amp::learn {

// One merge of the dendrogram, in the convention of SciPy's linkage and R's hclust(, "ward.D2"):
// leaves are 0..n-1, the cluster made by merge i is n + i; a < b.
struct WardMerge {
  int a = 0;
  int b = 0;
  // Ward distance sqrt(2 n_a n_b / (n_a + n_b)) * |mean_a - mean_b|: the merge raises the
  // within-cluster sum of squares by height^2 / 2.
  double height = 0.0;
  int size = 0;  // points in the merged cluster
};

// The full dendrogram: n - 1 merges by non-decreasing height.
struct WardDendrogram {
  int n = 0;
  std::vector<WardMerge> merges;
  // Labels (first-appearance order) of the c clusters left after the first n - c merges.
  std::vector<int> cut(int c) const;
};

// Agglomerative clustering with Ward's criterion (Ward 1963) by the nearest-neighbour chain
// algorithm (Murtagh 1983) on a full matrix of squared Ward distances updated by the Lance-Williams
// formula: O(n^2) time and memory. Merges are then sorted by height as SciPy does (Ward is reducible,
// so the chain's merges form a valid dendrogram in that order). Exact ties are broken by index.
WardDendrogram ward_linkage(const Eigen::MatrixXd& points, const core::StopCondition* stop = nullptr);

struct WardSettings {
  int max_clusters = 10;  // c tried: 1..max_clusters (at most n)
  void validate() const;  // throws ParameterError
};

// Ward clustering with the cut chosen by the elbow criterion (elbow.hpp). The curve comes from the
// dendrogram itself: W(c) = sum of height^2 / 2 over the first n - c merges, T = the sum over all.
// The Rng is not used: Ward is deterministic.
class WardClustering final : public Clusterer {
 public:
  explicit WardClustering(WardSettings settings = {});
  using Clusterer::cluster;
  Clustering cluster(const Eigen::MatrixXd& points, core::Rng& rng, const core::StopCondition* stop) const override;
  std::string_view name() const override { return "ward"; }

 private:
  WardSettings settings_;
};

}  // namespace amp::learn
