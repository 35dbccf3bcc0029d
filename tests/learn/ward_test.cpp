#include "amp/learn/ward.hpp"

#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/core/rng.hpp"
#include "amp/learn/adjusted_rand_index.hpp"

namespace amp::learn {
namespace {

Eigen::MatrixXd five_points() {
  Eigen::MatrixXd x(5, 1);
  x << 0, 1, 5, 7, 12;
  return x;
}

TEST(WardLinkage, HandComputedFivePoints) {
  // Points 0, 1, 5, 7, 12. Ward cost of a merge: dW = na nb / (na + nb) |ma - mb|^2, height sqrt(2 dW).
  //  1. {0}+{1}:        dW = 0.5 * 1        = 0.5   h = 1          -> cluster 5 (mean 0.5)
  //  2. {5}+{7}:        dW = 0.5 * 4        = 2     h = 2          -> cluster 6 (mean 6)
  //  3. {12}+{5,7}:     dW = 2/3 * 36       = 24    h = sqrt(48)   -> cluster 7 (mean 8)
  //     (beats {0,1}+{5,7}: 1 * 30.25 and {0,1}+{12}: 2/3 * 132.25)
  //  4. {0,1}+{5,7,12}: dW = 6/5 * 56.25    = 67.5  h = sqrt(135)  -> cluster 8
  // Sum of dW = 94 = total sum of squares about the mean 5 (25 + 16 + 0 + 4 + 49).
  // R 4.2.2 agrees: hclust(dist(c(0,1,5,7,12)), "ward.D2") gives merge (-1,-2) (-3,-4) (-5,2) (1,3)
  // and heights 1 2 6.92820323027551 11.61895003862225.
  const WardDendrogram tree = ward_linkage(five_points());
  ASSERT_EQ(tree.merges.size(), 4u);
  const int a[] = {0, 2, 4, 5}, b[] = {1, 3, 6, 7}, size[] = {2, 2, 3, 5};
  const double h[] = {1.0, 2.0, std::sqrt(48.0), std::sqrt(135.0)};
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(tree.merges[i].a, a[i]) << i;
    EXPECT_EQ(tree.merges[i].b, b[i]) << i;
    EXPECT_EQ(tree.merges[i].size, size[i]) << i;
    EXPECT_NEAR(tree.merges[i].height, h[i], 1e-12) << i;
  }
  EXPECT_EQ(tree.cut(1), (std::vector<int>{0, 0, 0, 0, 0}));
  EXPECT_EQ(tree.cut(2), (std::vector<int>{0, 0, 1, 1, 1}));
  EXPECT_EQ(tree.cut(3), (std::vector<int>{0, 0, 1, 1, 2}));
  EXPECT_EQ(tree.cut(5), (std::vector<int>{0, 1, 2, 3, 4}));
  EXPECT_THROW(tree.cut(6), ParameterError);
}

TEST(WardClustering, CurveFromTheDendrogramAndElbow) {
  // f(c) = W(c)/94: f = 1, 26.5/94, 2.5/94, 0.5/94, 0. d2(2) = 43.5/94, d2(3) = 22/94, d2(4) = 1.5/94.
  core::Rng rng(1);
  const Clustering out = WardClustering().cluster(five_points(), rng);
  ASSERT_EQ(out.curve.size(), 5u);
  const double f[] = {1.0, 26.5 / 94, 2.5 / 94, 0.5 / 94, 0.0};
  for (int c = 0; c < 5; ++c) EXPECT_NEAR(out.curve[c], f[c], 1e-14) << c + 1;
  EXPECT_EQ(out.c, 2);
  EXPECT_EQ(out.labels, (std::vector<int>{0, 0, 1, 1, 1}));
  EXPECT_DOUBLE_EQ(out.centres(0, 0), 0.5);
  EXPECT_DOUBLE_EQ(out.centres(1, 0), 8.0);
}

// Naive O(n^3) Ward: recompute every pairwise merge cost from cluster means and sizes.
std::vector<double> naive_ward_heights(const Eigen::MatrixXd& x, int cut_c, std::vector<int>& cut_labels) {
  const int n = static_cast<int>(x.rows());
  std::vector<Eigen::RowVectorXd> mean;
  std::vector<double> size;
  std::vector<std::vector<int>> members;
  for (int i = 0; i < n; ++i) {
    mean.push_back(x.row(i));
    size.push_back(1);
    members.push_back({i});
  }
  std::vector<double> heights;
  while (mean.size() > 1) {
    if (static_cast<int>(mean.size()) == cut_c) {
      cut_labels.assign(n, 0);
      for (std::size_t c = 0; c < members.size(); ++c)
        for (int i : members[c]) cut_labels[i] = static_cast<int>(c);
    }
    double best = std::numeric_limits<double>::infinity();
    std::size_t bi = 0, bj = 0;
    for (std::size_t i = 0; i < mean.size(); ++i)
      for (std::size_t j = i + 1; j < mean.size(); ++j) {
        const double d = 2.0 * size[i] * size[j] / (size[i] + size[j]) * (mean[i] - mean[j]).squaredNorm();
        if (d < best) best = d, bi = i, bj = j;
      }
    heights.push_back(std::sqrt(best));
    mean[bi] = (size[bi] * mean[bi] + size[bj] * mean[bj]) / (size[bi] + size[bj]);
    size[bi] += size[bj];
    members[bi].insert(members[bi].end(), members[bj].begin(), members[bj].end());
    mean.erase(mean.begin() + bj);
    size.erase(size.begin() + bj);
    members.erase(members.begin() + bj);
  }
  return heights;
}

TEST(WardLinkage, MatchesNaiveWardOnRandomPoints) {
  core::Rng rng(5);
  Eigen::MatrixXd x(60, 3);
  for (Eigen::Index i = 0; i < x.size(); ++i) x.data()[i] = rng.uniform(-5.0, 5.0);
  std::vector<int> naive_cut;
  const std::vector<double> heights = naive_ward_heights(x, 6, naive_cut);
  const WardDendrogram tree = ward_linkage(x);
  ASSERT_EQ(tree.merges.size(), heights.size());
  for (std::size_t i = 0; i < heights.size(); ++i) EXPECT_NEAR(tree.merges[i].height, heights[i], 1e-9) << i;
  EXPECT_EQ(tree.merges.back().size, 60);
  EXPECT_DOUBLE_EQ(adjusted_rand_index(tree.cut(6), naive_cut), 1.0);
  // Sum of height^2 / 2 = total sum of squares.
  double w = 0.0;
  for (const WardMerge& m : tree.merges) w += 0.5 * m.height * m.height;
  EXPECT_NEAR(w, (x.rowwise() - x.colwise().mean()).squaredNorm(), 1e-9);
}

TEST(WardLinkage, SinglePointAndDuplicates) {
  EXPECT_TRUE(ward_linkage(Eigen::MatrixXd::Zero(1, 2)).merges.empty());
  const WardDendrogram tree = ward_linkage(Eigen::MatrixXd::Constant(4, 2, 1.0));
  ASSERT_EQ(tree.merges.size(), 3u);
  for (const WardMerge& m : tree.merges) EXPECT_EQ(m.height, 0.0);
  core::Rng rng(1);
  EXPECT_EQ(WardClustering().cluster(Eigen::MatrixXd::Constant(4, 2, 1.0), rng).c, 1);
}

}  // namespace
}  // namespace amp::learn
