#pragma once
#include <cstddef>
#include <vector>

#include "amp/core/rng.hpp"

namespace amp::roadmap {

// Hybrid PRM's sampler selection (Hsu, Sanchez-Ante & Sun 2005; an EXP3-style adversarial bandit):
//   Pr(s) = (1 - gamma) * w(s) / sum w + gamma / |S|                      (selection probabilities)
//   after a sample of s:  w(s) <- w(s) * exp(gamma * rhat / |S|),  rhat = reward / (Pr(s) * cost)
// Weights start equal, so the first probabilities are uniform. Every probability stays >= gamma/|S|.
// Numerics: weights are kept as logarithms, shifted after every update so the largest is 0, and the
// probabilities are a max-shifted softmax of them: no overflow however large rhat gets, and arms whose
// weight underflows still keep their gamma/|S| share.
class SamplerBandit {
 public:
  // Throws ParameterError unless arms >= 1 and 0 < gamma <= 1.
  SamplerBandit(std::size_t arms, double gamma);

  std::size_t arms() const { return log_weights_.size(); }
  double gamma() const { return gamma_; }
  const std::vector<double>& probabilities() const { return probabilities_; }
  // log w(s) - max_s' log w(s').
  const std::vector<double>& log_weights() const { return log_weights_; }

  // An arm drawn by probabilities() (one uniform draw).
  std::size_t choose(core::Rng& rng) const;
  // The update above for arm s with reward >= 0 and cost > 0, Pr(s) being the current probability
  // (the one s was chosen with). Throws std::invalid_argument for a bad arm, reward or cost.
  void update(std::size_t s, double reward, double cost);

 private:
  void refresh();

  double gamma_;
  std::vector<double> log_weights_;
  std::vector<double> probabilities_;
};

}  // namespace amp::roadmap
