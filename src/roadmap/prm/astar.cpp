#include "amp/roadmap/prm/astar.hpp"

#include <algorithm>
#include <functional>
#include <limits>

namespace amp::roadmap {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr VertexId kNoParent = std::numeric_limits<VertexId>::max();
}  // namespace

bool AStar::search(const Roadmap& roadmap, const core::Space& space, VertexId start, VertexId goal,
                   std::vector<VertexId>& path) {
  path.clear();
  expanded_ = 0;
  const std::size_t n = roadmap.vertex_count();
  g_.assign(n, kInf);
  parent_.assign(n, kNoParent);
  heap_.clear();
  const State& target = roadmap.state(goal);
  auto h = [&](VertexId v) { return space.distance(roadmap.state(v), target); };
  // std::greater on (f, id) pops the smallest f, then the smallest id: deterministic tie-breaking.
  const auto cmp = std::greater<std::pair<double, VertexId>>();

  g_[start] = 0.0;
  heap_.emplace_back(h(start), start);
  while (!heap_.empty()) {
    std::pop_heap(heap_.begin(), heap_.end(), cmp);
    const auto [f, v] = heap_.back();
    heap_.pop_back();
    // Stale entry: v was reached more cheaply after this one was pushed (lazy deletion, which
    // also re-opens a vertex should rounding make the heuristic slightly inconsistent).
    if (f > g_[v] + h(v)) continue;
    ++expanded_;
    if (v == goal) break;
    for (const Edge& e : roadmap.edges(v)) {
      const double g = g_[v] + e.cost;
      if (g < g_[e.to]) {
        g_[e.to] = g;
        parent_[e.to] = v;
        heap_.emplace_back(g + h(e.to), e.to);
        std::push_heap(heap_.begin(), heap_.end(), cmp);
      }
    }
  }
  if (g_[goal] == kInf) return false;
  for (VertexId v = goal; v != kNoParent; v = parent_[v]) path.push_back(v);
  std::reverse(path.begin(), path.end());
  return true;
}

}  // namespace amp::roadmap
