#pragma once
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include "amp/roadmap/competence/competence_policy.hpp"
#include "amp/roadmap/competence/grid_astar_planner.hpp"
#include "amp/roadmap/planner.hpp"
#include "amp/roadmap/catalog/planner_registry.hpp"

namespace amp::roadmap {

// The A* grid planner with its threshold set per edge by a competence policy; reports what the
// searches did (calls abandoned for competence, cells checked, thresholds used). Keeps the moves of
// every accepted edge (a byte per grid step), so that a solution path costs no CD call to draw.
class CompetentLocalPlanner final : public LocalPlanner {
 public:
  CompetentLocalPlanner(std::unique_ptr<GridAStarPlanner> astar, std::unique_ptr<CompetencePolicy> policy);
  bool connect(const State& a, const State& b) override { return connect_edge(a, b, EdgeRequest{}); }
  bool connect_edge(const State& a, const State& b, const EdgeRequest& request) override;
  void edge_waypoints(const State& a, const State& b, const EdgeRequest& request, std::vector<State>& out) override;
  void report(std::map<std::string, double>& extra) const override;

 private:
  static std::uint64_t key(const EdgeRequest& r) { return (static_cast<std::uint64_t>(r.from) << 32) ^ r.to; }

  std::unique_ptr<GridAStarPlanner> astar_;
  std::unique_ptr<CompetencePolicy> policy_;
  std::unordered_map<std::uint64_t, std::vector<std::uint8_t>> moves_;  // by (from, to) of the request
  std::uint64_t calls_ = 0, abandoned_ = 0, exhausted_ = 0, cells_ = 0, move_checks_ = 0, repairs_ = 0;
  std::uint64_t capped_ = 0;
  double threshold_sum_ = 0.0, threshold_max_ = 0.0;
};

enum class CompetenceKind { kStatic, kGlobal, kLocal };  // PRM-C, PRM-G, PRM-L

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
  // k and the grid's fields; `value` is checked by its policy, its range is the catalog's per kind.
  static const core::SettingsSchema<CompetencePrmSettings>& schema();
  void validate() const;  // throws ParameterError
};

// {2, 4, 8, 16, 32} for o, {300, 1000, 3000, 9000} for s, {0.01, 0.03, 0.1, 0.3} for n.
const std::vector<double>& metaplanner_values(CompetenceKind kind);
// "o", "s" or "n".
const char* competence_parameter(CompetenceKind kind);

class CompetencePrm final : public Planner {
 public:
  explicit CompetencePrm(CompetencePrmSettings settings);
  PlanResult plan(const PlanningContext& ctx, const core::StopCondition& stop, core::Rng& rng) override;

 private:
  CompetencePrmSettings settings_;
};


}  // namespace amp::roadmap
