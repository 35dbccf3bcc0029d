#pragma once
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "amp/roadmap/competence/competence_policy.hpp"
#include "amp/roadmap/competence/grid_astar_planner.hpp"
#include "amp/roadmap/local_planners/local_planner.hpp"

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

}  // namespace amp::roadmap
