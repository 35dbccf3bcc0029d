// clusterer_choice.cpp: the clustering methods by name, and "auto", which keeps the method of the
// highest mean silhouette.
#include "amp/learn/clusterer_choice.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/core/rng.hpp"
#include "amp/core/stop_condition.hpp"
#include "amp/learn/adjusted_rand_index.hpp"
#include "amp/learn/silhouette.hpp"

namespace amp::learn {
namespace {

struct Blobs {
  Eigen::MatrixXd points;
  std::vector<int> truth;
};

// Three unit Gaussian blobs of 60, 80 and 100 points on a triangle of radius 10 (clusterer_test's
// "triangle2d" layout, drawn the same way).
Blobs triangle_blobs(std::uint64_t seed) {
  constexpr double kR = 10.0;
  const double h = kR * std::sqrt(3.0) / 2.0;
  const double centres[3][2] = {{kR, 0}, {-kR / 2, h}, {-kR / 2, -h}};
  const int sizes[3] = {60, 80, 100};
  core::Rng rng(seed);
  Blobs b{Eigen::MatrixXd(240, 2), {}};
  int row = 0;
  for (int c = 0; c < 3; ++c) {
    for (int i = 0; i < sizes[c]; ++i, ++row) {
      for (int j = 0; j < 2; ++j) b.points(row, j) = centres[c][j] + rng.normal();
      b.truth.push_back(c);
    }
  }
  return b;
}

TEST(AutoClusterer, StopsWhenTheRunsStopConditionFires) {
  const Blobs b = triangle_blobs(4);
  std::atomic<bool> cancel{true};
  const core::StopCondition cancelled(60.0, 1000000, &cancel);
  core::Rng rng(9);
  EXPECT_THROW(AutoClusterer().choose(b.points, rng, &cancelled), ClusteringStopped);
  EXPECT_THROW(mean_silhouette(b.points, b.truth, 3, &cancelled), ClusteringStopped);
}

TEST(MakeClusterer, EveryNameAndOnlyThose) {
  for (const std::string_view name : kClusteringNames) EXPECT_EQ(make_clusterer(name)->name(), name);
  try {
    make_clusterer("dbscan");
    FAIL() << "dbscan was accepted";
  } catch (const ParameterError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("'dbscan'"), std::string::npos) << m;
    EXPECT_NE(m.find("kmeans, ward, pgmeans or auto"), std::string::npos) << m;
  }
}

// The choice recomputed: each method on its own stream derived from one draw of the Rng, scored by
// its mean silhouette; the first of the highest scores wins, and cluster() returns its clustering.
TEST(AutoClusterer, KeepsTheFirstMethodOfTheHighestMeanSilhouette) {
  const Blobs b = triangle_blobs(7);
  core::Rng rng(3), copy(3), again(3);
  const ClusteringChoice choice = AutoClusterer().choose(b.points, rng);
  ASSERT_EQ(choice.methods, (std::vector<std::string>{"kmeans", "ward", "pgmeans"}));
  const std::uint64_t base = copy.next_u64();
  std::vector<double> scores;
  std::vector<Clustering> clusterings;
  for (std::uint64_t i = 0; i < 3; ++i) {
    core::Rng own(core::derive_seed(base, i));
    clusterings.push_back(make_clusterer(choice.methods[i])->cluster(b.points, own));
    scores.push_back(mean_silhouette(b.points, clusterings.back().labels, clusterings.back().c));
    EXPECT_EQ(choice.scores[i], scores.back()) << choice.methods[i];
    EXPECT_EQ(choice.clusters[i], clusterings.back().c) << choice.methods[i];
  }
  const auto best = static_cast<std::size_t>(std::max_element(scores.begin(), scores.end()) - scores.begin());
  EXPECT_EQ(choice.method, choice.methods[best]);
  EXPECT_EQ(choice.clustering.labels, clusterings[best].labels);
  EXPECT_EQ(AutoClusterer().cluster(b.points, again).labels, choice.clustering.labels);
  // Three well-separated blobs: the winner finds them.
  EXPECT_EQ(choice.clustering.c, 3);
  EXPECT_GT(adjusted_rand_index(choice.clustering.labels, b.truth), 0.95);
}

}  // namespace
}  // namespace amp::learn
