#include "amp/learn/pg_means.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <boost/math/distributions/normal.hpp>

#include "amp/core/error.hpp"
#include "amp/learn/kmeans.hpp"
#include "amp/learn/kolmogorov.hpp"

namespace amp::learn {

void PgMeansSettings::validate() const {
  if (projections < 1) throw ParameterError("pgmeans: projections: " + std::to_string(projections) + " < 1");
  if (!(alpha > 0.0 && alpha < 1.0)) throw ParameterError("pgmeans: alpha: " + std::to_string(alpha) + " outside (0, 1)");
  if (max_clusters < 1) throw ParameterError("pgmeans: max_clusters: " + std::to_string(max_clusters) + " < 1");
  if (new_cluster_trials < 1) {
    throw ParameterError("pgmeans: new_cluster_trials: " + std::to_string(new_cluster_trials) + " < 1");
  }
  em.validate();
}

ProjectionTest test_projections(const Eigen::MatrixXd& points, const GaussianMixture& model, int projections,
                                double alpha, core::Rng& rng, const core::StopCondition* stop) {
  const Eigen::Index n = points.rows();
  const Eigen::Index d = points.cols();
  const int k = model.k();
  const double critical = ks_critical_value(static_cast<int>(n), alpha);
  Eigen::VectorXd u(d);
  Eigen::VectorXd projected(n);
  std::vector<double> cdf(static_cast<std::size_t>(n));
  std::vector<boost::math::normal> components(static_cast<std::size_t>(k));
  ProjectionTest out;
  for (int p = 0; p < projections; ++p) {
    poll(stop);
    do {
      for (Eigen::Index i = 0; i < d; ++i) u[i] = rng.normal();
    } while (u.squaredNorm() == 0.0);
    u.normalize();
    projected.noalias() = points * u;
    std::sort(projected.data(), projected.data() + n);
    for (int j = 0; j < k; ++j) {  // projected component: N(u.mu_j, u' S_j u)
      const auto sj = static_cast<std::size_t>(j);
      const double var = u.dot(model.covariances[sj] * u);
      components[sj] = boost::math::normal(u.dot(model.means[sj]), std::sqrt(var));
    }
    for (Eigen::Index i = 0; i < n; ++i) {
      double f = 0.0;
      for (int j = 0; j < k; ++j) f += model.weights[j] * boost::math::cdf(components[static_cast<std::size_t>(j)], projected[i]);
      cdf[static_cast<std::size_t>(i)] = std::min(f, 1.0);
    }
    const double ratio = ks_statistic(cdf) / critical;
    out.worst_ratio = std::max(out.worst_ratio, ratio);
  }
  out.accepted = out.worst_ratio <= 1.0;
  return out;
}

PgMeans::PgMeans(PgMeansSettings settings) : settings_(settings) { settings_.validate(); }

EmFit PgMeans::add_cluster(const Eigen::MatrixXd& points, const EmFit& current, core::Rng& rng,
                          const core::StopCondition* stop) const {
  const Eigen::Index n = points.rows();
  const GaussianMixture& m = current.model;
  const int k = m.k();
  // Squared distance of each point to its nearest current mean: the k-means++ weights.
  std::vector<double> d2(static_cast<std::size_t>(n), std::numeric_limits<double>::infinity());
  for (Eigen::Index i = 0; i < n; ++i) {
    for (int j = 0; j < k; ++j) {
      d2[static_cast<std::size_t>(i)] = std::min(
          d2[static_cast<std::size_t>(i)], (points.row(i).transpose() - m.means[static_cast<std::size_t>(j)]).squaredNorm());
    }
  }
  Eigen::MatrixXd resp;
  Eigen::VectorXd ll;
  mixture_responsibilities(points, m, resp, ll);
  EmFit best;
  best.log_likelihood = -std::numeric_limits<double>::infinity();
  for (int t = 0; t < settings_.new_cluster_trials; ++t) {
    const auto pick = static_cast<Eigen::Index>(draw_by_weight(d2, rng.uniform01()));
    Eigen::Index owner = 0;
    resp.row(pick).maxCoeff(&owner);
    GaussianMixture init = m;
    const double half = 0.5 * m.weights[owner];
    init.weights.conservativeResize(k + 1);
    init.weights[owner] = half;
    init.weights[k] = half;
    init.means.push_back(points.row(pick).transpose());
    init.covariances.push_back(m.covariances[static_cast<std::size_t>(owner)]);
    EmFit fit = fit_em(points, std::move(init), settings_.em, stop);
    if (fit.log_likelihood > best.log_likelihood) best = std::move(fit);
  }
  return best;
}

Clustering PgMeans::cluster(const Eigen::MatrixXd& points, core::Rng& rng, const core::StopCondition* stop) const {
  validate_points(points, "pgmeans");
  const Eigen::Index n = points.rows();
  const int max_k = static_cast<int>(std::min<Eigen::Index>(settings_.max_clusters, n));
  Clustering out;
  EmFit fit = fit_em(points, single_gaussian(points, settings_.em.ridge), settings_.em, stop);
  for (;;) {
    const ProjectionTest test = test_projections(points, fit.model, settings_.projections, settings_.alpha, rng, stop);
    out.curve.push_back(test.worst_ratio);
    if (test.accepted || fit.model.k() >= max_k) break;
    fit = add_cluster(points, fit, rng, stop);
  }
  // Nearest mean (Euclidean) per point.
  const int k = fit.model.k();
  out.centres.resize(k, points.cols());
  for (int j = 0; j < k; ++j) out.centres.row(j) = fit.model.means[static_cast<std::size_t>(j)].transpose();
  out.labels.resize(static_cast<std::size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i) {
    Eigen::Index best = 0;
    (out.centres.rowwise() - points.row(i)).rowwise().squaredNorm().minCoeff(&best);
    out.labels[static_cast<std::size_t>(i)] = static_cast<int>(best);
  }
  out.c = canonicalise(out.labels, out.centres);
  return out;
}

}  // namespace amp::learn
