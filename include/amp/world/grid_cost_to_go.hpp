#pragma once
#include <cstdint>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

namespace amp::world {

// The cells a search may enter: width x height square cells of side cell_size, row-major with row 0
// the lowest y, and an optional cost per cell.
struct GridCells {
  int width = 0;
  int height = 0;
  double cell_size = 1.0;
  std::vector<std::uint8_t> free;  // nonzero: the cell may be entered
  // Extra cost per cell, >= 0 (empty: none). A step between cells a and b costs its length times
  // 1 + (cost[a] + cost[b]) / 2: the trapezoid rule along the step, so costs near obstacles make a
  // path keep away from them (Nav2's Smac planners charge length times 1 + penalty * cost / 252).
  std::vector<double> cost;
};

// Cost-to-goal of every cell of a grid: 8-connected, straight steps cost cell_size and diagonal ones
// sqrt(2) cell_size (times the cells' costs), and a diagonal step needs both cells beside it free (no
// corner cutting). compute() is value iteration ordered like Dijkstra, so every cell is settled once:
// a bucket queue whose buckets are one cell_size wide, the least step cost, so no cell can improve
// another of its own bucket and the order within a bucket does not matter (Dial's algorithm with
// real weights; Cherkassky, Goldberg & Radzik, "Shortest paths algorithms: theory and experimental
// evaluation", Math. Programming 73, 1996). The result is a universal plan: path() descends it from
// any start. Buffers are reused across goals.
class GridCostToGo {
 public:
  static constexpr double kUnreachable = std::numeric_limits<double>::infinity();
  // Largest cell cost accepted: the queue holds one bucket per cell_size of the longest step.
  static constexpr double kMaxCellCost = 1e4;

  // Throws ParameterError for a size that does not match, cell_size <= 0, or a cost that is
  // negative, not finite or above kMaxCellCost.
  explicit GridCostToGo(GridCells cells);

  const GridCells& cells() const { return cells_; }
  int index(int x, int y) const { return y * cells_.width + x; }
  bool free(int x, int y) const {
    return x >= 0 && y >= 0 && x < cells_.width && y < cells_.height && cells_.free[static_cast<std::size_t>(index(x, y))] != 0;
  }
  // Cost-to-goal field from `goal` (a cell index); every cell stays unreachable when the goal is
  // blocked. Throws ParameterError for an index outside the grid. `stop` (optional) is polled every
  // few thousand cells; returns false when it fired, or before settling a cell beyond `max_cells`
  // (the field is then incomplete).
  bool compute(int goal, const std::function<bool()>& stop = {},
               std::size_t max_cells = std::numeric_limits<std::size_t>::max());
  // Cells settled (given their final cost) by the last compute().
  std::size_t settled() const { return settled_; }
  int goal() const { return goal_; }
  // Cost from `cell` to the goal; kUnreachable for blocked and cut-off cells.
  double distance(int cell) const { return distance_[static_cast<std::size_t>(cell)]; }
  const std::vector<double>& distances() const { return distance_; }
  // Cells from start to the goal, both included, each step to the neighbour that realises the cost
  // (the maximum-likelihood action of the plan); empty when the start cannot reach the goal.
  std::vector<int> path(int start) const;
  // The neighbour of `cell` that realises its cost (one step of path()); -1 at the goal and for
  // blocked or unreachable cells.
  int next(int cell) const;

 private:
  struct Move {
    int dx, dy;
    double length;
  };
  bool legal(int x, int y, const Move& m) const;
  double step_cost(int from, int to, const Move& m) const;

  GridCells cells_;
  Move moves_[8];
  double bucket_width_ = 1.0;
  int goal_ = -1;
  std::size_t settled_ = 0;
  std::vector<double> distance_;
  std::vector<std::vector<std::pair<double, int>>> buckets_;  // circular, by floor(cost / bucket_width)
};

}  // namespace amp::world
