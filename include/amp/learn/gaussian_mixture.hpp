#pragma once
#include <vector>

#include <Eigen/Core>

#include "amp/learn/clusterer.hpp"

namespace amp::learn {

// A mixture of k Gaussians with full covariances in d dimensions.
struct GaussianMixture {
  Eigen::VectorXd weights;                   // k, sum 1
  std::vector<Eigen::VectorXd> means;        // k of d
  std::vector<Eigen::MatrixXd> covariances;  // k of d x d, positive definite
  int k() const { return static_cast<int>(weights.size()); }
};

struct EmSettings {
  int max_iterations = 200;
  double tolerance = 1e-7;  // stop when the mean log-likelihood per point gains less than this
  // Covariance regularisation: every M-step adds ridge * (trace of the data covariance / d) to the
  // diagonal, so covariances stay positive definite when a component collapses onto a line or a
  // point; the factor is scale-free (1e-6 of the average data variance).
  double ridge = 1e-6;
  void validate() const;  // throws ParameterError
};

struct EmFit {
  GaussianMixture model;
  double log_likelihood = 0.0;  // total over the points (natural log)
  int iterations = 0;
};

// Expectation-maximisation (Dempster, Laird & Rubin 1977) for a Gaussian mixture from `initial`.
// A component whose responsibility mass falls below one point keeps its previous mean and
// covariance (weight ~ 0) rather than producing a singular estimate.
EmFit fit_em(const Eigen::MatrixXd& points, GaussianMixture initial, const EmSettings& settings,
             const core::StopCondition* stop = nullptr);

// The single Gaussian of the data (sample mean, maximum-likelihood covariance + ridge).
GaussianMixture single_gaussian(const Eigen::MatrixXd& points, double ridge);

// The ridge actually added: ridge * trace(cov) / d (at least ridge itself, for constant data).
double ridge_value(const Eigen::MatrixXd& points, double ridge);

// Per-point log-likelihood log p(x_i) and responsibilities r(i, j) = P(component j | x_i).
void mixture_responsibilities(const Eigen::MatrixXd& points, const GaussianMixture& model,
                              Eigen::MatrixXd& responsibilities, Eigen::VectorXd& log_likelihood);

}  // namespace amp::learn
