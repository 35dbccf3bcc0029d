#pragma once
#include <vector>

#include <Eigen/Core>

#include "amp/core/settings_schema.hpp"
#include "amp/learn/centre_triangulation.hpp"
#include "amp/learn/pgcs_index.hpp"

namespace amp::learn {

struct PgcsSettings {
  // l, replacing n in the learning rate and the prior update (forgetting). 50,000: a walking
  // robot's stream is strongly correlated, and with a short window the clusters drift after it and
  // the rooms it left lose theirs. With M = 300 below: PGCS queries on the MovingAI rooms map (random
  // walk, 6 seeds) solve 67% against 48% with l = 10,000 and M = 10,000; the office 100% either way.
  int window = 50000;
  // While n < l, use n for l: the l most recent samples are all n there are. Without it, l = 50,000
  // gives the first cluster a learning rate of 1/50,000: the early clusters stay frozen where the
  // robot started (a chain of small clusters along its first path on the MovingAI rooms map) and the
  // rest of that room gets none.
  bool warm_up = true;
  // No insertion once this many clusters exist. 1,000: with 200 in the bundled 10 m office the
  // Voronoi cells span walls and desks, and PGCS queries solve 64% of random pairs against 93%
  // with 1,000 (problems/experiments/pgcs-sweep.yaml, 100,000 steps).
  int max_clusters = 1000;
  int insert_every = 100;       // N: an insertion every N steps
  // M: a deletion every M steps. 300: once max_clusters is reached only a deletion frees an
  // insertion, so M sets how fast the clusters left behind (small, on the robot's first paths) move
  // to where the map is still coarse (see window for the figures).
  int delete_every = 300;
  int delete_min_clusters = 3;  // deletions only while at least this many clusters exist
  double a_pi = 1.0;            // a_pi of phi = a_pi pi + a_sigma s2 / sum s2
  double a_sigma = 1.0;         // a_sigma of phi
  double sigma2_min = 1e-6;     // floor of every variance (the first cluster's 0 becomes this)
  double eta_max = 1.0;         // learning rates are clamped to (0, eta_max]
  int index_min_clusters = 32;  // below this many clusters the winner is found by a linear scan
  int index_leaf_size = 8;      // clusters per leaf of the winner index
  double posterior_tolerance = 1e-18;  // index: skip nodes whose share of eq. (2)'s sum is below this
  static const core::SettingsSchema<PgcsSettings>& schema();
  void validate() const { schema().validate(*this); }  // throws ParameterError
};

// Probabilistic growing cell structures for a 2-D stream, as in Vlassis, Papakonstantinou &
// Tsanakas, "Learning the Voronoi centers of a mobile robot's configuration space" (section 3), with
// the Delaunay triangulation of the centres (section 4) kept up to date.
//
// Decisions where the paper is silent:
// - Variance floor: every s2 is kept >= sigma2_min, the first cluster's included (with s2 = 0 the
//   Mahalanobis distance and log s2 are undefined).
// - The winner's s2 update uses the old centre: |xi - mu_old|^2, the stochastic-approximation (ML)
//   form; eta uses the prior before this step's prior update.
// - eta = p(k|xi) / (l pi_k) exceeds 1 when pi_k < p(k|xi) / l (a young cluster); it is clamped to
//   eta_max <= 1, since eta > 1 would throw mu past xi and could make s2 negative.
// - Note eq. (1) makes s2 a per-coordinate variance while the update tracks |xi - mu|^2, so s2 tends
//   to 2 s2 of the data (the paper's formula, kept as written).
// - Deletion renormalises the remaining priors (they sum to what they summed to before), in O(1)
//   through the lazy prior scale.
// - Insertion when q has no Delaunay neighbour (one cluster, or q hidden as a duplicate): f = q,
//   so r = (mu_q, s2_q, pi_q) and q halves its s2 and pi once; the priors then sum to more than 1,
//   and the prior update pulls the sum back (sum' - 1 = (1 - 1/l)(sum - 1)).
//
// Cost per step (K clusters): with K >= index_min_clusters the winner comes from PgcsIndex (exact),
// and eq. (2)'s denominator and the prior update visit only index leaves whose bound on
// exp(-c/2) relative to the winner's is >= posterior_tolerance (the skipped clusters' posteriors,
// each below that tolerance, are taken as 0: a relative error of at most K * tolerance in the sum).
// The update of all priors is exact and O(touched) through a lazy scale: pi_k = g ps_k, each step
// g *= 1 - 1/l and ps_k += p(k|xi) / (l g) for the visited clusters; the stored values are folded
// back (O(K)) when g falls below 1e-100. Insertion and deletion are O(K) every N and M steps.
class Pgcs {
 public:
  explicit Pgcs(PgcsSettings settings = {});  // throws ParameterError

  // One sample: the first one (with no cluster yet) initialises the first cluster; then the winner's
  // update, the prior update, and the insertion and deletion when due.
  void step(const Eigen::Vector2d& xi);

  // Adds a cluster as it is (for warm starts and tests); returns its id.
  int add_cluster(const Eigen::Vector2d& mu, double s2, double prior);
  // The insertion and deletion of section 3, now; return the new / removed id, -1 when none.
  int insert_cluster();
  int delete_cluster();

  // The winner criterion delta^2 + 2 log(2 pi s2) - 2 log pi of cluster k.
  double criterion(int k, const Eigen::Vector2d& xi) const;
  int winner(const Eigen::Vector2d& xi) const;         // the index when in use, else a scan
  int winner_linear(const Eigen::Vector2d& xi) const;  // ties: the lower id
  double posterior(int k, const Eigen::Vector2d& xi) const;  // eq. (2), exact (a scan)
  double phi(int k) const;

  const std::vector<int>& ids() const { return alive_; }  // live cluster ids, ascending
  int size() const { return static_cast<int>(alive_.size()); }
  const Eigen::Vector2d& mean(int k) const { return mu_[k]; }
  double variance(int k) const { return s2_[k]; }
  double prior(int k) const { return scale_ * ps_[k]; }
  long steps() const { return steps_; }
  const CentreTriangulation& triangulation() const { return dt_; }
  const PgcsSettings& settings() const { return settings_; }

  struct StepRecord {
    int winner = -1;
    double posterior = 0.0;  // p(winner | xi)
    double eta = 0.0;        // after the clamp
    int visited = 0;         // clusters in eq. (2)'s sum
  };
  const StepRecord& last_step() const { return last_; }

 private:
  int new_id();
  void adapt(const Eigen::Vector2d& xi);
  void rebuild_index();
  void fold_scale();
  bool use_index() const { return size() >= settings_.index_min_clusters; }

  PgcsSettings settings_;
  std::vector<Eigen::Vector2d> mu_;  // by id
  std::vector<double> s2_, ps_;      // by id; prior = scale_ * ps_
  std::vector<int> alive_, free_;
  double scale_ = 1.0, log_scale_ = 0.0;
  double prior_sum_ = 0.0;  // sum of the priors
  double s2_sum_ = 0.0;     // sum of the variances (phi)
  long steps_ = 0;
  CentreTriangulation dt_;
  PgcsIndex index_;
  std::vector<int> touched_;      // scratch: clusters in eq. (2)'s sum
  std::vector<double> weights_;   // scratch: their exp(-(c - c_min) / 2)
  std::vector<int> neighbours_;   // scratch
  StepRecord last_;
};

}  // namespace amp::learn
