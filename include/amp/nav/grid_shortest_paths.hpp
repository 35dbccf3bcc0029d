#pragma once
#include <limits>
#include <utility>
#include <vector>

#include "amp/nav/free_mask.hpp"

namespace amp::nav {

// Shortest paths on the free cells of a FreeMask: 8-connected, straight steps cost cell_size and
// diagonal ones sqrt(2) cell_size, and a diagonal step needs both cells beside it free (no corner
// cutting, so no path squeezes between two blocked cells that touch at a corner). compute() runs
// Dijkstra (binary heap, lazy deletion) from a goal cell and leaves the cost-to-goal of every cell:
// a universal plan that path() follows from any start. Buffers are reused across goals.
class GridShortestPaths {
 public:
  static constexpr double kUnreachable = std::numeric_limits<double>::infinity();

  explicit GridShortestPaths(FreeMask mask);

  const FreeMask& mask() const { return mask_; }
  // Cost-to-goal field from `goal` (a cell index); every cell stays unreachable when the goal is
  // blocked. Throws ParameterError for an index outside the mask.
  void compute(int goal);
  int goal() const { return goal_; }
  // Cost from `cell` to the goal; kUnreachable for blocked and cut-off cells.
  double distance(int cell) const { return distance_[static_cast<std::size_t>(cell)]; }
  const std::vector<double>& distances() const { return distance_; }
  // Cells from start to the goal, both included, each step to the neighbour that realises the cost;
  // empty when the start cannot reach the goal.
  std::vector<int> path(int start) const;

 private:
  struct Move {
    int dx, dy;
    double cost;
  };
  // Whether the step from (x, y) by m stays on free cells without cutting a corner.
  bool legal(int x, int y, const Move& m) const;

  FreeMask mask_;
  Move moves_[8];
  int goal_ = -1;
  std::vector<double> distance_;
  std::vector<std::pair<double, int>> heap_;  // Dijkstra's open list
};

}  // namespace amp::nav
