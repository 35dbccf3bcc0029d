#include "amp/learn/gaussian_mixture.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <utility>

#include <Eigen/Cholesky>

#include "amp/core/error.hpp"
#include "amp/learn/clusterer.hpp"

namespace amp::learn {
namespace {

constexpr double kMinMass = 1.0;  // a component needs one point's worth of responsibility to move

}  // namespace

void EmSettings::validate() const {
  if (max_iterations < 1) throw ParameterError("em: max_iterations: " + std::to_string(max_iterations) + " < 1");
  if (!(tolerance >= 0.0)) throw ParameterError("em: tolerance: " + std::to_string(tolerance) + " < 0");
  if (!(ridge > 0.0)) throw ParameterError("em: ridge: " + std::to_string(ridge) + " <= 0");
}

double ridge_value(const Eigen::MatrixXd& points, double ridge) {
  const Eigen::MatrixXd centred = points.rowwise() - points.colwise().mean();
  const double mean_variance = centred.squaredNorm() / static_cast<double>(points.rows() * points.cols());
  return ridge * (mean_variance > 0.0 ? mean_variance : 1.0);
}

GaussianMixture single_gaussian(const Eigen::MatrixXd& points, double ridge) {
  const Eigen::Index d = points.cols();
  const Eigen::RowVectorXd mean = points.colwise().mean();
  const Eigen::MatrixXd centred = points.rowwise() - mean;
  GaussianMixture g;
  g.weights = Eigen::VectorXd::Ones(1);
  g.means.push_back(mean.transpose());
  g.covariances.push_back(centred.transpose() * centred / static_cast<double>(points.rows()) +
                          ridge_value(points, ridge) * Eigen::MatrixXd::Identity(d, d));
  return g;
}

void mixture_responsibilities(const Eigen::MatrixXd& points, const GaussianMixture& model,
                              Eigen::MatrixXd& responsibilities, Eigen::VectorXd& log_likelihood) {
  const Eigen::Index n = points.rows();
  const Eigen::Index d = points.cols();
  const int k = model.k();
  responsibilities.resize(n, k);
  log_likelihood.resize(n);
  Eigen::VectorXd diff(d);
  for (int j = 0; j < k; ++j) {
    const Eigen::LLT<Eigen::MatrixXd> llt(model.covariances[static_cast<std::size_t>(j)]);
    if (llt.info() != Eigen::Success) throw Error("em: covariance of component " + std::to_string(j) + " not positive definite");
    const double log_det = 2.0 * llt.matrixLLT().diagonal().array().log().sum();
    const double log_norm = std::log(model.weights[j]) - 0.5 * (static_cast<double>(d) * std::log(2.0 * std::numbers::pi) + log_det);
    for (Eigen::Index i = 0; i < n; ++i) {
      diff = points.row(i).transpose() - model.means[static_cast<std::size_t>(j)];
      llt.matrixL().solveInPlace(diff);
      responsibilities(i, j) = log_norm - 0.5 * diff.squaredNorm();  // log(pi_j N(x_i | mu_j, S_j))
    }
  }
  for (Eigen::Index i = 0; i < n; ++i) {  // log-sum-exp per point
    const double m = responsibilities.row(i).maxCoeff();
    double s = 0.0;
    for (int j = 0; j < k; ++j) s += std::exp(responsibilities(i, j) - m);
    log_likelihood[i] = m + std::log(s);
    for (int j = 0; j < k; ++j) responsibilities(i, j) = std::exp(responsibilities(i, j) - log_likelihood[i]);
  }
}

EmFit fit_em(const Eigen::MatrixXd& points, GaussianMixture initial, const EmSettings& settings,
             const core::StopCondition* stop) {
  settings.validate();
  validate_points(points, "em");
  const Eigen::Index n = points.rows();
  const Eigen::Index d = points.cols();
  const double ridge = ridge_value(points, settings.ridge);
  EmFit fit;
  fit.model = std::move(initial);
  const int k = fit.model.k();
  Eigen::MatrixXd resp;
  Eigen::VectorXd ll;
  Eigen::VectorXd diff(d);
  double previous = -std::numeric_limits<double>::infinity();
  for (int it = 0; it < settings.max_iterations; ++it) {
    poll(stop);
    mixture_responsibilities(points, fit.model, resp, ll);  // E-step
    fit.log_likelihood = ll.sum();
    fit.iterations = it + 1;
    const double mean_ll = fit.log_likelihood / static_cast<double>(n);
    if (mean_ll - previous < settings.tolerance) break;  // EM never lowers it; converged
    previous = mean_ll;
    for (int j = 0; j < k; ++j) {  // M-step
      const double mass = resp.col(j).sum();
      fit.model.weights[j] = mass / static_cast<double>(n);
      if (mass < kMinMass) continue;
      Eigen::VectorXd& mu = fit.model.means[static_cast<std::size_t>(j)];
      mu = points.transpose() * resp.col(j) / mass;
      Eigen::MatrixXd& cov = fit.model.covariances[static_cast<std::size_t>(j)];
      cov.setZero();
      for (Eigen::Index i = 0; i < n; ++i) {
        diff = points.row(i).transpose() - mu;
        cov.selfadjointView<Eigen::Lower>().rankUpdate(diff, resp(i, j));
      }
      for (Eigen::Index c = 1; c < d; ++c) {  // rankUpdate filled the lower triangle only
        for (Eigen::Index r = 0; r < c; ++r) cov(r, c) = cov(c, r);
      }
      cov /= mass;
      cov.diagonal().array() += ridge;
    }
    fit.model.weights /= fit.model.weights.sum();
  }
  return fit;
}

}  // namespace amp::learn
