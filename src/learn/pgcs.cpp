#include "amp/learn/pgcs.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "amp/core/error.hpp"

namespace amp::learn {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// The lazy prior scale is folded into the stored priors below this (they grow as 1 / scale).
constexpr double kMinPriorScale = 1e-100;

}  // namespace

const core::SettingsSchema<PgcsSettings>& PgcsSettings::schema() {
  using S = PgcsSettings;
  static const core::SettingsSchema<S> schema(
      "pgcs",
      {core::integer_field<S>("window", &S::window, 1, 1e9, "l: learning rate p/(l pi) and prior step 1/l"),
       core::bool_field<S>("warm_up", &S::warm_up, "use n instead of l while fewer than l samples have come"),
       core::integer_field<S>("max_clusters", &S::max_clusters, 3, 1e6, "no insertion beyond this many clusters"),
       core::integer_field<S>("insert_every", &S::insert_every, 1, 1e9, "N: steps between insertions"),
       core::integer_field<S>("delete_every", &S::delete_every, 1, 1e9, "M: steps between deletions"),
       core::integer_field<S>("delete_min_clusters", &S::delete_min_clusters, 2, 1e6,
                              "deletions only while at least this many clusters exist"),
       core::real_field<S>("a_pi", &S::a_pi, 0, 1e6, "weight of the prior in phi"),
       core::real_field<S>("a_sigma", &S::a_sigma, 0, 1e6, "weight of the variance share in phi"),
       core::real_field<S>("sigma2_min", &S::sigma2_min, 1e-300, 1e300, "floor of the variances"),
       core::real_field<S>("eta_max", &S::eta_max, 1e-12, 1, "learning rates are clamped to (0, eta_max]"),
       core::integer_field<S>("index_min_clusters", &S::index_min_clusters, 1, 1e9,
                              "clusters from which the winner index replaces a linear scan"),
       core::integer_field<S>("index_leaf_size", &S::index_leaf_size, 1, 4096, "clusters per index leaf"),
       core::real_field<S>("posterior_tolerance", &S::posterior_tolerance, 0, 1e-3,
                           "index: clusters whose share of the posterior sum is below this are skipped")});
  return schema;
}

Pgcs::Pgcs(PgcsSettings settings) : settings_(settings), index_(settings.index_leaf_size) {
  settings_.validate();
  if (!(settings_.a_pi + settings_.a_sigma > 0.0)) throw ParameterError("pgcs: a_pi + a_sigma must be positive");
  const auto cap = static_cast<std::size_t>(settings_.max_clusters) + 1;
  mu_.reserve(cap);
  s2_.reserve(cap);
  ps_.reserve(cap);
  alive_.reserve(cap);
  touched_.reserve(cap);
  weights_.reserve(cap);
}

double Pgcs::criterion(int k, const Eigen::Vector2d& xi) const {
  // Section 3: delta^2 + 2 log(2 pi s2) - 2 log pi, i.e. -2 log(pi_k p_k(xi)) of eqs. (1)-(2).
  const double s2 = s2_[k];
  return (xi - mu_[k]).squaredNorm() / s2 + 2.0 * std::log(2.0 * std::numbers::pi * s2) -
         2.0 * (log_scale_ + std::log(ps_[k]));
}

int Pgcs::winner_linear(const Eigen::Vector2d& xi) const {
  int best = -1;
  double best_c = kInf;
  for (int k : alive_) {  // ascending: strict < keeps the lower id on ties
    const double c = criterion(k, xi);
    if (c < best_c || best < 0) {
      best_c = c;
      best = k;
    }
  }
  return best;
}

int Pgcs::winner(const Eigen::Vector2d& xi) const {
  if (!use_index() || index_.empty()) return winner_linear(xi);
  int best = -1;
  double best_c = kInf;
  index_.search(xi, log_scale_, kInf, [&](int k) {
    const double c = criterion(k, xi);
    if (best < 0 || c < best_c || (c == best_c && k < best)) {
      best_c = c;
      best = k;
    }
    return best_c;
  });
  return best;
}

double Pgcs::posterior(int k, const Eigen::Vector2d& xi) const {
  // Eq. (2), with every term divided by the largest (pi_j p_j = exp(-c_j / 2)) against underflow.
  const double c_min = criterion(winner_linear(xi), xi);
  double sum = 0.0;
  for (int j : alive_) sum += std::exp(-0.5 * (criterion(j, xi) - c_min));
  return std::exp(-0.5 * (criterion(k, xi) - c_min)) / sum;
}

double Pgcs::phi(int k) const {
  // Section 3, cluster insertion: phi = a_pi pi + a_sigma s2 / sum_j s2_j.
  return settings_.a_pi * prior(k) + settings_.a_sigma * s2_[k] / s2_sum_;
}

int Pgcs::new_id() {
  if (!free_.empty()) {  // free_ is descending: reuse the smallest free id
    const int id = free_.back();
    free_.pop_back();
    return id;
  }
  mu_.emplace_back(Eigen::Vector2d::Zero());
  s2_.push_back(0.0);
  ps_.push_back(0.0);
  return static_cast<int>(mu_.size()) - 1;
}

int Pgcs::add_cluster(const Eigen::Vector2d& mu, double s2, double prior) {
  if (!(prior >= 0.0) || !std::isfinite(prior) || !std::isfinite(s2) || !mu.allFinite()) {
    throw ParameterError("pgcs: a cluster needs a finite centre and variance and a prior >= 0, got prior " +
                         std::to_string(prior));
  }
  const int id = new_id();
  mu_[id] = mu;
  s2_[id] = std::max(s2, settings_.sigma2_min);
  ps_[id] = prior / scale_;
  alive_.insert(std::upper_bound(alive_.begin(), alive_.end(), id), id);
  prior_sum_ += prior;
  s2_sum_ += s2_[id];
  dt_.insert(id, mu);
  rebuild_index();
  return id;
}

void Pgcs::rebuild_index() {
  if (use_index()) index_.build(alive_, mu_, s2_, ps_);
}

void Pgcs::fold_scale() {
  for (int k : alive_) ps_[k] *= scale_;
  scale_ = 1.0;
  log_scale_ = 0.0;
  rebuild_index();
}

void Pgcs::step(const Eigen::Vector2d& xi) {
  ++steps_;
  if (alive_.empty()) {
    add_cluster(xi, 0.0, 1.0);  // initialisation: mu_1 = xi_1, s2_1 = 0 (floored), pi_1 = 1
    last_ = {alive_[0], 1.0, 0.0, 1};
  } else {
    adapt(xi);
  }
  if (steps_ % settings_.insert_every == 0 && insert_cluster() < 0) rebuild_index();  // re-tightens the index
  if (steps_ % settings_.delete_every == 0) delete_cluster();
}

void Pgcs::adapt(const Eigen::Vector2d& xi) {
  // l, or n while fewer than l samples have come (the l most recent samples are then all n of them:
  // the paper's stochastic approximation until the window fills).
  const double l = settings_.warm_up ? static_cast<double>(std::min<long>(steps_, settings_.window)) : settings_.window;
  const int w = winner(xi);
  const double c_min = criterion(w, xi);
  // Eq. (2)'s terms relative to the winner's: exp(-(c_j - c_min) / 2) <= 1, the winner's = 1.
  touched_.clear();
  weights_.clear();
  double sum = 0.0;
  auto visit = [&](int k) {
    const double wk = std::exp(-0.5 * (criterion(k, xi) - c_min));
    touched_.push_back(k);
    weights_.push_back(wk);
    sum += wk;
  };
  if (use_index() && !index_.empty() && settings_.posterior_tolerance > 0.0) {
    const double limit = c_min - 2.0 * std::log(settings_.posterior_tolerance);  // exp(-(c - c_min)/2) >= tol
    index_.search(xi, log_scale_, limit, [&](int k) {
      visit(k);
      return limit;
    });
  } else {
    for (int k : alive_) visit(k);
  }

  // Adaptation of the winner (section 3), with eta from the prior before this step's update.
  const double p_w = 1.0 / sum;  // the winner's weight is exp(0) = 1
  const double eta = std::min(p_w / (l * prior(w)), settings_.eta_max);
  const Eigen::Vector2d diff = xi - mu_[w];  // xi - mu_old
  mu_[w] += eta * diff;
  const double s2_old = s2_[w];
  s2_[w] = std::max(s2_old + eta * (diff.squaredNorm() - s2_old), settings_.sigma2_min);
  s2_sum_ += s2_[w] - s2_old;

  // Prior update of all clusters: pi_k += (p(k|xi) - pi_k) / l, through the lazy scale.
  if (settings_.window == 1) {  // pi_k = p(k|xi): the scale would be 0, so this case is O(K log K) a step
    for (int k : alive_) ps_[k] = 0.0;
    scale_ = 1.0;
    log_scale_ = 0.0;
    for (std::size_t i = 0; i < touched_.size(); ++i) ps_[touched_[i]] = weights_[i] / sum;
    prior_sum_ = 1.0;
    rebuild_index();
  } else {
    scale_ *= 1.0 - 1.0 / l;
    log_scale_ = std::log(scale_);
    const double step = 1.0 / (l * scale_ * sum);
    for (std::size_t i = 0; i < touched_.size(); ++i) ps_[touched_[i]] += weights_[i] * step;
    prior_sum_ += (1.0 - prior_sum_) / l;  // the posteriors sum to one
    if (scale_ < kMinPriorScale) {
      fold_scale();
    } else if (use_index() && !index_.empty()) {
      for (int k : touched_) index_.touch(k, mu_[k], s2_[k], ps_[k]);
    }
  }
  dt_.move(w, mu_[w]);
  last_ = {w, p_w, eta, static_cast<int>(touched_.size())};
}

int Pgcs::insert_cluster() {
  if (alive_.empty() || size() >= settings_.max_clusters) return -1;
  s2_sum_ = 0.0;  // exact again (the per-step updates accumulate rounding)
  for (int k : alive_) s2_sum_ += s2_[k];
  int q = alive_[0];
  for (int k : alive_) {
    if (phi(k) > phi(q)) q = k;
  }
  dt_.neighbours(q, neighbours_);
  int f = q;  // no neighbour: q splits with itself (see the class comment)
  for (int k : neighbours_) {
    if (f == q || phi(k) > phi(f)) f = k;
  }
  const double phi_q = phi(q), phi_f = phi(f), total = phi_q + phi_f;
  const double wq = phi_q / total, wf = phi_f / total;
  // Section 3, cluster insertion: r between q and f, weighted by phi.
  const Eigen::Vector2d mu_r = wq * mu_[q] + wf * mu_[f];
  const double s2_r = wq * s2_[q] + wf * s2_[f];
  const double pi_r = wq * prior(q) + wf * prior(f);
  if (f != q) {
    // The shrink: s2_q(new) = (1 - phi_q / (phi_q + phi_f)) s2_q, likewise pi_q, s2_f and pi_f.
    s2_[q] = std::max((1.0 - wq) * s2_[q], settings_.sigma2_min);
    s2_[f] = std::max((1.0 - wf) * s2_[f], settings_.sigma2_min);
    ps_[q] *= 1.0 - wq;
    ps_[f] *= 1.0 - wf;  // pi_r + pi_q(new) + pi_f(new) = pi_q + pi_f
  } else {
    s2_[q] = std::max(0.5 * s2_[q], settings_.sigma2_min);
    ps_[q] *= 0.5;
    prior_sum_ -= prior(q);  // add_cluster adds pi_r = 2 pi_q(new)
  }
  s2_sum_ = 0.0;
  for (int k : alive_) s2_sum_ += s2_[k];
  return add_cluster(mu_r, s2_r, pi_r);
}

int Pgcs::delete_cluster() {
  if (size() < settings_.delete_min_clusters) return -1;
  s2_sum_ = 0.0;
  for (int k : alive_) s2_sum_ += s2_[k];
  int c = alive_[0];
  for (int k : alive_) {
    if (phi(k) < phi(c)) c = k;
  }
  // Section 3, cluster deletion; the others' priors are renormalised to the sum they had.
  const double pi_c = prior(c);
  if (prior_sum_ - pi_c > 0.0) {
    scale_ *= prior_sum_ / (prior_sum_ - pi_c);
    log_scale_ = std::log(scale_);
  }
  s2_sum_ -= s2_[c];
  alive_.erase(std::find(alive_.begin(), alive_.end(), c));
  free_.insert(std::upper_bound(free_.begin(), free_.end(), c, std::greater<int>()), c);
  dt_.remove(c);
  rebuild_index();
  return c;
}

}  // namespace amp::learn
