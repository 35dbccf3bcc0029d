#pragma once
#include <Eigen/Core>

#include "amp/learn/clusterer.hpp"
#include "amp/learn/gaussian_mixture.hpp"

namespace amp::learn {

struct PgMeansSettings {
  int projections = 12;       // random 1-D projections tested per model
  double alpha = 0.001;       // KS test level per projection
  int max_clusters = 20;      // k never exceeds this (nor n)
  int new_cluster_trials = 10; // candidate initialisations of each added cluster; best likelihood kept
  EmSettings em;
  void validate() const;      // throws ParameterError
};

// The per-model test of PG-means: the worst projection's KS statistic over its critical value.
struct ProjectionTest {
  double worst_ratio = 0.0;  // max over projections of D / D_crit; the model is accepted iff <= 1
  bool accepted = true;
};

// Projects data and mixture onto `projections` random unit directions u (normalised standard
// normal vectors from rng) and tests each with a one-sample KS test of the projected points against
// the projected mixture, a 1-D mixture of normals with CDF sum_j pi_j Phi((x - u.mu_j) / sqrt(u' S_j u))
// (Boost.Math normal), at critical value ks_critical_value(n, alpha) (asymptotic Kolmogorov law with
// Stephens' finite-n scaling; see kolmogorov.hpp).
ProjectionTest test_projections(const Eigen::MatrixXd& points, const GaussianMixture& model, int projections,
                                double alpha, core::Rng& rng, const core::StopCondition* stop = nullptr);

// PG-means (Feng & Hamerly, "PG-means: learning the number of clusters in data", NIPS 2006):
// fit a Gaussian mixture by EM starting from k = 1; test the fit by test_projections; while some
// projection rejects, add one cluster and refit; stop when all accept or at max_clusters. Final
// labels assign each point to the nearest mixture mean (Euclidean, as the UAS paper says);
// a mean nearest to no point is dropped, so c <= k.
//
// A new cluster (paper section 3: several random new centres, keep the best likelihood) is tried
// new_cluster_trials times: its mean is a data point drawn k-means++ style (probability ~ squared
// distance to the nearest current mean), its covariance that of the component most responsible for
// the point, and the two share that component's weight; each candidate is refined by EM and the
// highest log-likelihood wins.
//
// The KS critical value assumes a fully specified model, but the model was fitted to the same data,
// so the test is conservative (Lilliefors' effect): it tends to accept, i.e. to under- rather than
// over-split. Feng & Hamerly calibrate by simulation instead; we use the computed value, as the UAS paper does.
class PgMeans final : public Clusterer {
 public:
  explicit PgMeans(PgMeansSettings settings = {});
  using Clusterer::cluster;
  Clustering cluster(const Eigen::MatrixXd& points, core::Rng& rng, const core::StopCondition* stop) const override;
  std::string_view name() const override { return "pgmeans"; }

 private:
  EmFit add_cluster(const Eigen::MatrixXd& points, const EmFit& current, core::Rng& rng,
                    const core::StopCondition* stop) const;
  PgMeansSettings settings_;
};

}  // namespace amp::learn
