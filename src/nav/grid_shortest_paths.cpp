#include "amp/nav/grid_shortest_paths.hpp"

#include <cmath>
#include <functional>
#include <numbers>
#include <algorithm>
#include <string>

#include "amp/core/error.hpp"

namespace amp::nav {

GridShortestPaths::GridShortestPaths(FreeMask mask) : mask_(std::move(mask)) {
  const double s = mask_.cell_size(), d = std::numbers::sqrt2 * mask_.cell_size();
  const Move moves[8] = {{1, 0, s},  {-1, 0, s}, {0, 1, s},  {0, -1, s},
                         {1, 1, d},  {-1, 1, d}, {1, -1, d}, {-1, -1, d}};
  std::copy(std::begin(moves), std::end(moves), moves_);
  distance_.assign(mask_.cell_count(), kUnreachable);
  heap_.reserve(mask_.cell_count());
}

bool GridShortestPaths::legal(int x, int y, const Move& m) const {
  if (!mask_.free(x + m.dx, y + m.dy)) return false;
  return m.dx == 0 || m.dy == 0 || (mask_.free(x + m.dx, y) && mask_.free(x, y + m.dy));
}

void GridShortestPaths::compute(int goal) {
  if (goal < 0 || static_cast<std::size_t>(goal) >= mask_.cell_count()) {
    throw ParameterError("goal cell " + std::to_string(goal) + " is outside the " + std::to_string(mask_.width()) +
                         " x " + std::to_string(mask_.height()) + " grid");
  }
  goal_ = goal;
  std::fill(distance_.begin(), distance_.end(), kUnreachable);
  if (!mask_.free(goal)) return;
  // A binary heap (std::push_heap / pop_heap, min-first) on a vector that keeps its capacity from
  // one goal to the next.
  using Entry = std::pair<double, int>;
  std::vector<Entry>& heap = heap_;
  heap.clear();
  const std::greater<Entry> later;
  distance_[static_cast<std::size_t>(goal)] = 0.0;
  heap.emplace_back(0.0, goal);
  const int w = mask_.width();
  while (!heap.empty()) {
    std::pop_heap(heap.begin(), heap.end(), later);
    const auto [d, cell] = heap.back();
    heap.pop_back();
    if (d > distance_[static_cast<std::size_t>(cell)]) continue;  // a stale entry
    const int x = cell % w, y = cell / w;
    for (const Move& m : moves_) {
      if (!legal(x, y, m)) continue;
      const int next = mask_.index(x + m.dx, y + m.dy);
      const double nd = d + m.cost;
      if (nd < distance_[static_cast<std::size_t>(next)]) {
        distance_[static_cast<std::size_t>(next)] = nd;
        heap.emplace_back(nd, next);
        std::push_heap(heap.begin(), heap.end(), later);
      }
    }
  }
}

std::vector<int> GridShortestPaths::path(int start) const {
  std::vector<int> out;
  if (goal_ < 0 || start < 0 || static_cast<std::size_t>(start) >= mask_.cell_count() ||
      distance(start) == kUnreachable) {
    return out;
  }
  const int w = mask_.width();
  int cell = start;
  out.push_back(cell);
  // Every step strictly lowers the cost (steps cost >= cell_size), so this ends at the goal.
  while (cell != goal_ && out.size() <= mask_.cell_count()) {
    const int x = cell % w, y = cell / w;
    int best = -1;
    double best_cost = kUnreachable;
    for (const Move& m : moves_) {
      if (!legal(x, y, m)) continue;
      const int next = mask_.index(x + m.dx, y + m.dy);
      const double c = distance(next) + m.cost;
      if (c < best_cost) {
        best_cost = c;
        best = next;
      }
    }
    cell = best;
    out.push_back(cell);
  }
  return out;
}

}  // namespace amp::nav
