#pragma once
#include <vector>

#include "amp/roadmap/competence/competence_policy.hpp"
#include "amp/roadmap/competence/competent_local_planner.hpp"
#include "amp/roadmap/competence/grid_astar_planner.hpp"
#include "amp/roadmap/planner.hpp"

namespace amp::roadmap {

// Isto et al.'s PRM: uniform pseudo-random samples, each joined to up to k nearest vertices of each
// connected component by the competence-controlled A* grid planner, until every seed is in one
// component. `value` is o, s or n; the run record carries it under that name. The paper's
// metaplanner, which draws the value per run from metaplanner_values(), is the benchmark
// harness's `draw:` (docs/experiment-format.md), as for any planner parameter.
struct CompetencePrmSettings {
  CompetenceKind kind = CompetenceKind::kLocal;
  double value = 0.1;
  int k = 10;
  GridAStarSettings grid;
  // k and the grid's fields; `value` is checked against competence_spec(kind).
  static const core::SettingsSchema<CompetencePrmSettings>& schema();
  void validate() const;  // throws ParameterError
};

// {2, 4, 8, 16, 32} for o, {300, 1000, 3000, 9000} for s, {0.01, 0.03, 0.1, 0.3} for n.
const std::vector<double>& metaplanner_values(CompetenceKind kind);

class CompetencePrm final : public Planner {
 public:
  explicit CompetencePrm(CompetencePrmSettings settings);
  PlanResult plan(const PlanningContext& ctx, const core::StopCondition& stop, core::Rng& rng) override;

 private:
  CompetencePrmSettings settings_;
};


}  // namespace amp::roadmap
