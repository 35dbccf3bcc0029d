#include "amp/learn/pg_means.hpp"

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/core/rng.hpp"

namespace amp::learn {
namespace {

Eigen::MatrixXd blob(Eigen::Index n, Eigen::Index d, double shift, core::Rng& rng) {
  Eigen::MatrixXd x(n, d);
  for (Eigen::Index i = 0; i < x.size(); ++i) x.data()[i] = rng.normal();
  x.col(0).array() += shift;
  return x;
}

TEST(PgMeans, SingleBlobIsOneCluster) {
  for (int d = 2; d <= 3; ++d) {
    for (std::uint64_t seed : {1u, 2u, 3u}) {
      core::Rng data_rng(seed);
      const Eigen::MatrixXd x = blob(200, d, 0.0, data_rng);
      core::Rng rng(seed + 100);
      const Clustering out = PgMeans().cluster(x, rng);
      EXPECT_EQ(out.c, 1) << "d " << d << " seed " << seed;
      ASSERT_EQ(out.curve.size(), 1u);
      EXPECT_LE(out.curve[0], 1.0);
    }
  }
}

TEST(TestProjections, RejectsOneGaussianForTwoBlobsAndAcceptsTheTrueModel) {
  core::Rng data_rng(4);
  Eigen::MatrixXd x(400, 2);
  x << blob(200, 2, -4.0, data_rng), blob(200, 2, 4.0, data_rng);
  core::Rng rng(9);
  const ProjectionTest one = test_projections(x, single_gaussian(x, 1e-6), 12, 0.001, rng);
  EXPECT_FALSE(one.accepted);
  EXPECT_GT(one.worst_ratio, 1.0);
  GaussianMixture truth;
  truth.weights = Eigen::Vector2d(0.5, 0.5);
  truth.means = {Eigen::Vector2d(-4, 0), Eigen::Vector2d(4, 0)};
  truth.covariances = {Eigen::MatrixXd::Identity(2, 2), Eigen::MatrixXd::Identity(2, 2)};
  const ProjectionTest two = test_projections(x, truth, 12, 0.001, rng);
  EXPECT_TRUE(two.accepted);
  EXPECT_LE(two.worst_ratio, 1.0);
}

TEST(PgMeans, TwoBlobsGiveTwoClustersWithCentresNearTheTruth) {
  core::Rng data_rng(5);
  Eigen::MatrixXd x(300, 2);
  x << blob(100, 2, -5.0, data_rng), blob(200, 2, 5.0, data_rng);
  core::Rng rng(6);
  const Clustering out = PgMeans().cluster(x, rng);
  ASSERT_EQ(out.c, 2);
  EXPECT_EQ(out.curve.size(), 2u);
  EXPECT_GT(out.curve[0], 1.0);
  EXPECT_LE(out.curve[1], 1.0);
  EXPECT_NEAR(out.centres(0, 0), -5.0, 0.3);  // first point belongs to the left blob
  EXPECT_NEAR(out.centres(1, 0), 5.0, 0.3);
}

TEST(PgMeans, MaxClustersCapsK) {
  core::Rng data_rng(5);
  Eigen::MatrixXd x(300, 2);
  x << blob(100, 2, -5.0, data_rng), blob(200, 2, 5.0, data_rng);
  PgMeansSettings s;
  s.max_clusters = 1;
  core::Rng rng(6);
  EXPECT_EQ(PgMeans(s).cluster(x, rng).c, 1);
  s.alpha = 0.0;
  EXPECT_THROW(PgMeans{s}, ParameterError);
}

}  // namespace
}  // namespace amp::learn
