#include "amp/roadmap/competence/competence_policy.hpp"

#include <algorithm>
#include <cmath>

#include "amp/core/error.hpp"

namespace amp::roadmap {

StaticCompetence::StaticCompetence(double o) : o_(o) {
  if (!(o >= 1.0) || !std::isfinite(o)) throw ParameterError("prm-c: o must be a number >= 1 (O(C) is never below 1)");
}

GlobalCompetence::GlobalCompetence(double s) : s_(s) {
  if (!(s > 0.0) || !std::isfinite(s)) throw ParameterError("prm-g: s must be a positive number");
}

double GlobalCompetence::threshold(const EdgeRequest& edge) {
  if (edge.roadmap_size > 0) last_size_ = edge.roadmap_size;
  // A threshold of 0 would be rejected by the planner; a tiny one refuses every search alike.
  return std::max(static_cast<double>(last_size_) / s_ * 32.0, 1e-9);
}

LocalCompetence::LocalCompetence(double n) : n_(n) {
  if (!(n > 0.0) || !std::isfinite(n)) throw ParameterError("prm-l: n must be a positive number");
}

double LocalCompetence::success_ratio(std::size_t v) const {
  if (v >= calls_.size()) return 1.0;
  return (successes_[v] + 1.0) / (calls_[v] + 1.0);
}

double LocalCompetence::threshold(const EdgeRequest& edge) {
  return std::max(vertex_threshold(edge.from), vertex_threshold(edge.to));
}

void LocalCompetence::count(std::size_t v, bool success) {
  if (v == EdgeRequest::kNoVertex) return;
  if (v >= calls_.size()) {
    calls_.resize(v + 1, 0);
    successes_.resize(v + 1, 0);
  }
  ++calls_[v];
  if (success) ++successes_[v];
}

void LocalCompetence::record(const EdgeRequest& edge, bool success) {
  count(edge.from, success);
  count(edge.to, success);
}

}  // namespace amp::roadmap
