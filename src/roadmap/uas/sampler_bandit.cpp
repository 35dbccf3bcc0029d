#include "amp/roadmap/uas/sampler_bandit.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "amp/core/error.hpp"

namespace amp::roadmap {

SamplerBandit::SamplerBandit(std::size_t arms, double gamma)
    : gamma_(gamma), log_weights_(arms, 0.0), probabilities_(arms, 0.0) {
  if (arms == 0) throw ParameterError("hybrid prm: at least one sampler is needed");
  if (!(gamma > 0.0 && gamma <= 1.0)) {
    throw ParameterError("hybrid prm: gamma must be in (0, 1], got " + std::to_string(gamma));
  }
  refresh();
}

std::size_t SamplerBandit::choose(core::Rng& rng) const {
  const double u = rng.uniform01();
  double cumulative = 0.0;
  for (std::size_t s = 0; s + 1 < probabilities_.size(); ++s) {
    cumulative += probabilities_[s];
    if (u < cumulative) return s;
  }
  return probabilities_.size() - 1;  // also absorbs rounding of the cumulative sum
}

void SamplerBandit::update(std::size_t s, double reward, double cost) {
  if (s >= arms() || !(reward >= 0.0) || !std::isfinite(reward) || !(cost > 0.0) || !std::isfinite(cost)) {
    throw std::invalid_argument("SamplerBandit::update: bad arm, reward or cost");
  }
  const double n = static_cast<double>(arms());
  const double r_hat = reward / (probabilities_[s] * cost);
  log_weights_[s] += gamma_ * r_hat / n;  // log of w(s) * exp(gamma * rhat / |S|)
  refresh();
}

void SamplerBandit::refresh() {
  const double top = *std::max_element(log_weights_.begin(), log_weights_.end());
  double sum = 0.0;
  for (double& lw : log_weights_) {
    lw -= top;  // w / sum w is unchanged by a common factor
    sum += std::exp(lw);
  }
  const double n = static_cast<double>(arms());
  for (std::size_t i = 0; i < arms(); ++i) {
    probabilities_[i] = (1.0 - gamma_) * std::exp(log_weights_[i]) / sum + gamma_ / n;
  }
}

}  // namespace amp::roadmap
