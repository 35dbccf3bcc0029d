#include "amp/learn/silhouette.hpp"

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/core/rng.hpp"
#include "amp/learn/adjusted_rand_index.hpp"
#include "amp/learn/clusterer_choice.hpp"

namespace amp::learn {
namespace {

TEST(Silhouette, MatchesAHandComputedExample) {
  // Points 0, 1 | 10, 11 on a line. Point 0: a = 1, b = (10 + 11) / 2 = 10.5, s = 9.5 / 10.5;
  // point 1: a = 1, b = (9 + 10) / 2 = 9.5, s = 8.5 / 9.5; the other two mirror them.
  Eigen::MatrixXd x(4, 1);
  x << 0, 1, 10, 11;
  const double expected = (9.5 / 10.5 + 8.5 / 9.5) / 2.0;
  EXPECT_NEAR(mean_silhouette(x, {0, 0, 1, 1}, 2), expected, 1e-15);
  // A bad split scores negative: {0, 10} and {1, 11}. Point 0: a = 10, b = mean(1, 11) = 6, s = -0.4;
  // point 1: a = 10, b = mean(1, 9) = 5, s = -0.5; point 10: -0.5; point 11: -0.4.
  EXPECT_NEAR(mean_silhouette(x, {0, 1, 0, 1}, 2), -0.45, 1e-15);
  // A singleton scores 0: {0} alone, {1, 10, 11}: only the three others count, over n = 4.
  // Point 1: a = mean(9, 10) = 9.5, b = 1 -> (1 - 9.5) / 9.5; point 10: a = mean(9, 1) = 5, b = 10 ->
  // (10 - 5) / 10; point 11: a = mean(10, 1) = 5.5, b = 11 -> (11 - 5.5) / 11.
  const double single = ((1 - 9.5) / 9.5 + 0.5 + 0.5) / 4.0;
  EXPECT_NEAR(mean_silhouette(x, {0, 1, 1, 1}, 2), single, 1e-15);
  EXPECT_EQ(mean_silhouette(x, {0, 0, 0, 0}, 1), 0.0);  // one cluster: no structure
}

Eigen::MatrixXd three_blobs(core::Rng& rng, std::vector<int>& truth) {
  const double centres[3][2] = {{0, 0}, {10, 0}, {5, 9}};
  Eigen::MatrixXd x(150, 2);
  truth.clear();
  for (int i = 0; i < 150; ++i) {
    const int b = i % 3;
    x(i, 0) = rng.normal(centres[b][0], 0.8);
    x(i, 1) = rng.normal(centres[b][1], 0.8);
    truth.push_back(b);
  }
  return x;
}

TEST(AutoClusterer, PicksAMethodThatFindsSeparatedBlobsAndSaysWhichAndWhy) {
  core::Rng data(4);
  std::vector<int> truth;
  const Eigen::MatrixXd x = three_blobs(data, truth);
  core::Rng rng(9);
  const ClusteringChoice c = AutoClusterer().choose(x, rng);
  ASSERT_EQ(c.methods, (std::vector<std::string>{"kmeans", "ward", "pgmeans"}));
  ASSERT_EQ(c.scores.size(), 3u);
  EXPECT_EQ(c.clustering.c, 3);
  EXPECT_GT(adjusted_rand_index(c.clustering.labels, truth), 0.95);
  // The winner has the highest silhouette, and its score is the silhouette of its labels.
  std::size_t w = 0;
  for (std::size_t i = 0; i < 3; ++i) if (c.methods[i] == c.method) w = i;
  for (double s : c.scores) EXPECT_LE(s, c.scores[w]);
  EXPECT_NEAR(c.scores[w], mean_silhouette(x, c.clustering.labels, c.clustering.c), 1e-12);
  // Same input and seed: same choice.
  core::Rng again(9);
  EXPECT_EQ(AutoClusterer().choose(x, again).clustering.labels, c.clustering.labels);
}

TEST(MakeClusterer, KnowsTheFourNamesAndRejectsOthers) {
  for (const char* n : {"kmeans", "ward", "pgmeans", "auto"}) EXPECT_EQ(make_clusterer(n)->name(), n);
  try {
    make_clusterer("dbscan");
    FAIL();
  } catch (const ParameterError& e) {
    EXPECT_NE(std::string(e.what()).find("kmeans, ward, pgmeans or auto"), std::string::npos);
  }
}

}  // namespace
}  // namespace amp::learn
