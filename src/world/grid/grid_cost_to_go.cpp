#include "amp/world/grid_cost_to_go.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "amp/core/error.hpp"

namespace amp::world {

GridCostToGo::GridCostToGo(GridCells cells) : cells_(std::move(cells)) {
  const GridCells& c = cells_;
  if (c.width < 1 || c.height < 1) {
    throw ParameterError("grid: width and height must be >= 1, got " + std::to_string(c.width) + " x " +
                         std::to_string(c.height));
  }
  if (!(c.cell_size > 0.0) || !std::isfinite(c.cell_size)) {
    throw ParameterError("grid: cell size must be positive, got " + std::to_string(c.cell_size));
  }
  const std::size_t n = static_cast<std::size_t>(c.width) * static_cast<std::size_t>(c.height);
  if (c.free.size() != n) {
    throw ParameterError("grid: " + std::to_string(c.free.size()) + " free flags for " + std::to_string(n) + " cells");
  }
  if (!c.cost.empty() && c.cost.size() != n) {
    throw ParameterError("grid: " + std::to_string(c.cost.size()) + " cell costs for " + std::to_string(n) + " cells");
  }
  double max_cost = 0.0;
  for (double v : c.cost) {
    if (!(v >= 0.0) || v > kMaxCellCost) {
      throw ParameterError("grid: a cell cost must be in [0, " + std::to_string(kMaxCellCost) + "], got " +
                           std::to_string(v));
    }
    max_cost = std::max(max_cost, v);
  }
  const double s = c.cell_size, d = std::numbers::sqrt2 * c.cell_size;
  const Move moves[8] = {{1, 0, s}, {-1, 0, s}, {0, 1, s}, {0, -1, s}, {1, 1, d}, {-1, 1, d}, {1, -1, d}, {-1, -1, d}};
  std::copy(std::begin(moves), std::end(moves), moves_);
  bucket_width_ = s;  // the least step cost (costs are >= 0)
  // A step lands at most floor(longest / width) + 1 buckets ahead of the one being emptied.
  const double longest = d * (1.0 + max_cost);
  buckets_.resize(static_cast<std::size_t>(std::ceil(longest / bucket_width_)) + 2);
  distance_.assign(n, kUnreachable);
}

bool GridCostToGo::legal(int x, int y, const Move& m) const {
  if (!free(x + m.dx, y + m.dy)) return false;
  return m.dx == 0 || m.dy == 0 || (free(x + m.dx, y) && free(x, y + m.dy));
}

double GridCostToGo::step_cost(int from, int to, const Move& m) const {
  if (cells_.cost.empty()) return m.length;
  return m.length * (1.0 + 0.5 * (cells_.cost[static_cast<std::size_t>(from)] + cells_.cost[static_cast<std::size_t>(to)]));
}

bool GridCostToGo::compute(int goal, const std::function<bool()>& stop, std::size_t max_cells) {
  if (goal < 0 || static_cast<std::size_t>(goal) >= distance_.size()) {
    throw ParameterError("goal cell " + std::to_string(goal) + " is outside the " + std::to_string(cells_.width) +
                         " x " + std::to_string(cells_.height) + " grid");
  }
  goal_ = goal;
  settled_ = 0;
  std::fill(distance_.begin(), distance_.end(), kUnreachable);
  if (cells_.free[static_cast<std::size_t>(goal)] == 0) return true;
  for (auto& b : buckets_) b.clear();
  const long ring = static_cast<long>(buckets_.size());
  distance_[static_cast<std::size_t>(goal)] = 0.0;
  buckets_[0].emplace_back(0.0, goal);
  std::size_t pending = 1;
  const int w = cells_.width;
  std::size_t popped = 0;
  for (long i = 0; pending > 0; ++i) {
    auto& bucket = buckets_[static_cast<std::size_t>(i % ring)];
    while (!bucket.empty()) {
      const auto [d, cell] = bucket.back();
      bucket.pop_back();
      --pending;
      if (stop && (++popped & 4095) == 0 && stop()) return false;
      if (d > distance_[static_cast<std::size_t>(cell)]) continue;  // a stale entry
      if (settled_ == max_cells) return false;
      ++settled_;
      const int x = cell % w, y = cell / w;
      for (const Move& m : moves_) {
        if (!legal(x, y, m)) continue;
        const int next = index(x + m.dx, y + m.dy);
        const double nd = d + step_cost(cell, next, m);
        if (nd < distance_[static_cast<std::size_t>(next)]) {
          distance_[static_cast<std::size_t>(next)] = nd;
          // Never into the bucket being emptied (rounding could put nd a hair below its floor).
          const long k = std::max(i + 1, static_cast<long>(nd / bucket_width_));
          buckets_[static_cast<std::size_t>(k % ring)].emplace_back(nd, next);
          ++pending;
        }
      }
    }
  }
  return true;
}

int GridCostToGo::next(int cell) const {
  if (goal_ < 0 || cell == goal_ || cell < 0 || static_cast<std::size_t>(cell) >= distance_.size() ||
      distance(cell) == kUnreachable) {
    return -1;
  }
  const int w = cells_.width, x = cell % w, y = cell / w;
  int best = -1;
  double best_cost = kUnreachable;
  for (const Move& m : moves_) {
    if (!legal(x, y, m)) continue;
    const int n = index(x + m.dx, y + m.dy);
    const double c = distance(n) + step_cost(cell, n, m);
    if (c < best_cost) {
      best_cost = c;
      best = n;
    }
  }
  return best;
}

std::vector<int> GridCostToGo::path(int start) const {
  std::vector<int> out;
  if (goal_ < 0 || start < 0 || static_cast<std::size_t>(start) >= distance_.size() || distance(start) == kUnreachable) {
    return out;
  }
  // Every step strictly lowers the cost-to-goal (steps cost >= cell_size), so this ends at the goal.
  for (int cell = start; cell >= 0 && out.size() <= distance_.size(); cell = next(cell)) out.push_back(cell);
  return out;
}

}  // namespace amp::world
