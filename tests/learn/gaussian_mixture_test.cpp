#include "amp/learn/gaussian_mixture.hpp"

#include <cmath>
#include <numbers>

#include <Eigen/Cholesky>
#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/core/rng.hpp"

namespace amp::learn {
namespace {

// n draws of N(mean, L L^T) appended at row `at`.
void draw(Eigen::MatrixXd& x, Eigen::Index at, Eigen::Index n, const Eigen::Vector2d& mean, const Eigen::Matrix2d& l,
          core::Rng& rng) {
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Vector2d z(rng.normal(), rng.normal());
    x.row(at + i) = (mean + l * z).transpose();
  }
}

TEST(SingleGaussian, MeanAndMaximumLikelihoodCovariancePlusRidge) {
  Eigen::MatrixXd x(4, 2);
  x << 0, 0,  //
      2, 0,   //
      0, 2,   //
      2, 2;
  // Mean (1, 1); ML covariance diag(1, 1); mean data variance 1, so the ridge is 1e-3 * 1.
  const GaussianMixture g = single_gaussian(x, 1e-3);
  EXPECT_TRUE(g.means[0].isApprox(Eigen::Vector2d(1, 1)));
  EXPECT_TRUE(g.covariances[0].isApprox(Eigen::Matrix2d::Identity() * 1.001));
  EXPECT_DOUBLE_EQ(g.weights[0], 1.0);
}

TEST(MixtureResponsibilities, HandComputedOneDimensional) {
  // Components N(0, 1) and N(4, 1), weights 1/2: at x = 2 both densities equal, so r = (1/2, 1/2)
  // and log p = log phi(2).
  GaussianMixture m;
  m.weights = Eigen::Vector2d(0.5, 0.5);
  m.means = {Eigen::VectorXd::Constant(1, 0.0), Eigen::VectorXd::Constant(1, 4.0)};
  m.covariances = {Eigen::MatrixXd::Identity(1, 1), Eigen::MatrixXd::Identity(1, 1)};
  Eigen::MatrixXd r;
  Eigen::VectorXd ll;
  mixture_responsibilities(Eigen::MatrixXd::Constant(1, 1, 2.0), m, r, ll);
  EXPECT_NEAR(r(0, 0), 0.5, 1e-15);
  EXPECT_NEAR(ll[0], -2.0 - 0.5 * std::log(2.0 * std::numbers::pi), 1e-14);
}

TEST(FitEm, RecoversTwoAnisotropicComponentsAndNeverLowersTheLikelihood) {
  core::Rng rng(21);
  Eigen::MatrixXd x(600, 2);
  Eigen::Matrix2d l1, l2;
  l1 << 2.0, 0.0, 1.0, 0.5;  // covariance L L^T = [[4, 2], [2, 1.25]]
  l2 << 0.5, 0.0, 0.0, 1.5;  // covariance diag(0.25, 2.25)
  draw(x, 0, 200, Eigen::Vector2d(0, 0), l1, rng);
  draw(x, 200, 400, Eigen::Vector2d(12, 6), l2, rng);
  GaussianMixture init;
  init.weights = Eigen::Vector2d(0.5, 0.5);
  init.means = {Eigen::Vector2d(2, 2), Eigen::Vector2d(9, 4)};
  init.covariances = {Eigen::MatrixXd::Identity(2, 2), Eigen::MatrixXd::Identity(2, 2)};
  double previous = -std::numeric_limits<double>::infinity();
  for (int iterations = 1; iterations <= 8; ++iterations) {
    EmSettings s;
    s.max_iterations = iterations;
    s.tolerance = 0.0;
    const double ll = fit_em(x, init, s).log_likelihood;
    EXPECT_GE(ll, previous - 1e-9) << iterations;
    previous = ll;
  }
  const EmFit fit = fit_em(x, init, EmSettings{});
  EXPECT_NEAR(fit.model.weights[0], 1.0 / 3.0, 1e-6);  // separation: responsibilities are ~0/1
  EXPECT_LT((fit.model.means[0] - Eigen::Vector2d(0, 0)).norm(), 0.3);
  EXPECT_LT((fit.model.means[1] - Eigen::Vector2d(12, 6)).norm(), 0.3);
  EXPECT_LT((fit.model.covariances[0] - l1 * l1.transpose()).norm(), 0.8);
  EXPECT_LT((fit.model.covariances[1] - l2 * l2.transpose()).norm(), 0.4);
  EXPECT_THROW(fit_em(x, init, EmSettings{0, 1e-7, 1e-6}), ParameterError);
}

TEST(FitEm, RidgeKeepsACollapsedComponentPositiveDefinite) {
  // All points on a line: the ML covariance is singular; with the ridge it factorises.
  Eigen::MatrixXd x(20, 2);
  for (int i = 0; i < 20; ++i) x.row(i) << i, 2.0 * i;
  const EmFit fit = fit_em(x, single_gaussian(x, 1e-6), EmSettings{});
  EXPECT_EQ(Eigen::LLT<Eigen::MatrixXd>(fit.model.covariances[0]).info(), Eigen::Success);
  EXPECT_TRUE(std::isfinite(fit.log_likelihood));
}

}  // namespace
}  // namespace amp::learn
