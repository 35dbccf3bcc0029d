#include "amp/roadmap/competence/competence_policy.hpp"

#include <algorithm>
#include <cmath>

#include "amp/core/error.hpp"

namespace amp::roadmap {

namespace {
// Checks `value` against the form's spec, with the catalog's own one-line message.
double checked(CompetenceKind kind, const char* planner, double value) {
  const core::ParamSpec& spec = competence_spec(kind);
  core::Params(planner, {spec}, {{spec.name, value}});
  return value;
}
}  // namespace

const core::ParamSpec& competence_spec(CompetenceKind kind) {
  // O(C) is never below 1, so o < 1 refuses every search; s and n scale O_th and must be positive.
  static const core::ParamSpec o{"o", core::ParamType::kReal, 8.0, 1, 1e6, {}, "O_th, fixed"};
  static const core::ParamSpec s{"s", core::ParamType::kReal, 1000.0, 1, 1e9, {}, "roadmap size at which O_th = 32"};
  static const core::ParamSpec n{
      "n", core::ParamType::kReal, 0.1, 0.001, 1000, {}, "scale of O_th over a vertex's failure ratio"};
  return kind == CompetenceKind::kStatic ? o : kind == CompetenceKind::kGlobal ? s : n;
}

const char* competence_parameter(CompetenceKind kind) { return competence_spec(kind).name.c_str(); }

StaticCompetence::StaticCompetence(double o) : o_(checked(CompetenceKind::kStatic, "prm-c", o)) {}

GlobalCompetence::GlobalCompetence(double s) : s_(checked(CompetenceKind::kGlobal, "prm-g", s)) {}

double GlobalCompetence::threshold(const EdgeRequest& edge) {
  if (edge.roadmap_size > 0) last_size_ = edge.roadmap_size;
  // A threshold of 0 would be rejected by the planner; a tiny one refuses every search alike.
  return std::max(static_cast<double>(last_size_) / s_ * 32.0, 1e-9);
}

LocalCompetence::LocalCompetence(double n) : n_(checked(CompetenceKind::kLocal, "prm-l", n)) {}

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
