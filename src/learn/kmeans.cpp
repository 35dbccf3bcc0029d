#include "amp/learn/kmeans.hpp"

#include <algorithm>
#include <limits>
#include <string>

#include "amp/core/error.hpp"
#include "amp/learn/elbow.hpp"

namespace amp::learn {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Nearest column of centres (d x k) to x; ties go to the lower index.
int nearest(const Eigen::MatrixXd& centres, const Eigen::Ref<const Eigen::VectorXd>& x, double& d2) {
  int best = 0;
  d2 = kInf;
  for (Eigen::Index j = 0; j < centres.cols(); ++j) {
    const double d = (centres.col(j) - x).squaredNorm();
    if (d < d2) {
      d2 = d;
      best = static_cast<int>(j);
    }
  }
  return best;
}

}  // namespace

std::size_t draw_by_weight(std::span<const double> weights, double u) {
  double total = 0.0;
  for (double w : weights) total += w;
  if (!(total > 0.0)) {
    return std::min(weights.size() - 1, static_cast<std::size_t>(u * static_cast<double>(weights.size())));
  }
  const double target = u * total;
  double prefix = 0.0;
  std::size_t last_positive = 0;
  for (std::size_t i = 0; i < weights.size(); ++i) {
    if (weights[i] <= 0.0) continue;
    prefix += weights[i];
    last_positive = i;
    if (target < prefix) return i;
  }
  return last_positive;  // rounding left target at the very top
}

KMeansFit lloyd(const Eigen::MatrixXd& points, Eigen::MatrixXd centres, int max_iterations,
                const core::StopCondition* stop) {
  const Eigen::Index n = points.rows();
  const Eigen::Index k = centres.rows();
  const Eigen::MatrixXd x = points.transpose();  // d x n: each point contiguous
  Eigen::MatrixXd c = centres.transpose();       // d x k
  Eigen::MatrixXd sums(x.rows(), k);
  Eigen::VectorXd counts(k);
  Eigen::VectorXd dist(n);
  KMeansFit fit;
  fit.labels.assign(static_cast<std::size_t>(n), -1);
  for (int it = 0; it < max_iterations; ++it) {
    poll(stop);
    bool changed = false;
    for (Eigen::Index i = 0; i < n; ++i) {
      const int l = nearest(c, x.col(i), dist[i]);
      if (l != fit.labels[static_cast<std::size_t>(i)]) {
        fit.labels[static_cast<std::size_t>(i)] = l;
        changed = true;
      }
    }
    ++fit.iterations;
    if (!changed) break;  // centres are already the means of this assignment
    sums.setZero();
    counts.setZero();
    for (Eigen::Index i = 0; i < n; ++i) {
      const int l = fit.labels[static_cast<std::size_t>(i)];
      sums.col(l) += x.col(i);
      counts[l] += 1.0;
    }
    for (Eigen::Index j = 0; j < k; ++j) {
      if (counts[j] > 0.0) {
        c.col(j) = sums.col(j) / counts[j];
      } else {  // empty: take the worst-served point, and stop it counting as worst again
        Eigen::Index far = 0;
        dist.maxCoeff(&far);
        c.col(j) = x.col(far);
        dist[far] = 0.0;
      }
    }
  }
  // Final labels are the nearest centres of the final centres (after max_iterations they may lag).
  fit.wcss = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    fit.labels[static_cast<std::size_t>(i)] = nearest(c, x.col(i), dist[i]);
    fit.wcss += dist[i];
  }
  fit.centres = c.transpose();
  return fit;
}

Eigen::MatrixXd kmeans_pp_seeds(const Eigen::MatrixXd& points, int k, core::Rng& rng,
                                const core::StopCondition* stop) {
  const Eigen::Index n = points.rows();
  Eigen::MatrixXd seeds(k, points.cols());
  std::vector<double> d2(static_cast<std::size_t>(n), kInf);
  std::size_t pick = rng.uniform_index(static_cast<std::uint64_t>(n));
  for (int j = 0; j < k; ++j) {
    poll(stop);
    if (j > 0) pick = draw_by_weight(d2, rng.uniform01());
    seeds.row(j) = points.row(static_cast<Eigen::Index>(pick));
    for (Eigen::Index i = 0; i < n; ++i) {
      d2[static_cast<std::size_t>(i)] =
          std::min(d2[static_cast<std::size_t>(i)], (points.row(i) - seeds.row(j)).squaredNorm());
    }
  }
  return seeds;
}

KMeansFit fit_kmeans(const Eigen::MatrixXd& points, int k, int restarts, int max_iterations, core::Rng& rng,
                     const core::StopCondition* stop) {
  validate_points(points, "kmeans");
  if (k < 1 || k > points.rows()) {
    throw ParameterError("kmeans: k: " + std::to_string(k) + " outside 1.." + std::to_string(points.rows()));
  }
  KMeansFit best;
  best.wcss = kInf;
  for (int r = 0; r < restarts; ++r) {
    KMeansFit fit = lloyd(points, kmeans_pp_seeds(points, k, rng, stop), max_iterations, stop);
    if (fit.wcss < best.wcss) best = std::move(fit);
  }
  return best;
}

void KMeansSettings::validate() const {
  if (max_clusters < 1) throw ParameterError("kmeans: max_clusters: " + std::to_string(max_clusters) + " < 1");
  if (restarts < 1) throw ParameterError("kmeans: restarts: " + std::to_string(restarts) + " < 1");
  if (max_iterations < 1) {
    throw ParameterError("kmeans: max_iterations: " + std::to_string(max_iterations) + " < 1");
  }
}

KMeans::KMeans(KMeansSettings settings) : settings_(settings) { settings_.validate(); }

Clustering KMeans::cluster(const Eigen::MatrixXd& points, core::Rng& rng, const core::StopCondition* stop) const {
  validate_points(points, "kmeans");
  const int max_c = static_cast<int>(std::min<Eigen::Index>(settings_.max_clusters, points.rows()));
  const double total = total_sum_of_squares(points);
  std::vector<KMeansFit> fits;
  Clustering out;
  for (int c = 1; c <= max_c; ++c) {
    fits.push_back(fit_kmeans(points, c, settings_.restarts, settings_.max_iterations, rng, stop));
    out.curve.push_back(total > 0.0 ? fits.back().wcss / total : 0.0);
  }
  out.curve[0] = total > 0.0 ? 1.0 : 0.0;  // W(1) = T exactly; avoids 1 +- rounding
  const int c = elbow_choice(out.curve);
  KMeansFit& chosen = fits[static_cast<std::size_t>(c - 1)];
  out.labels = std::move(chosen.labels);
  out.centres = std::move(chosen.centres);
  out.c = canonicalise(out.labels, out.centres);
  return out;
}

}  // namespace amp::learn
