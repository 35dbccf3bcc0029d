#include "amp/roadmap/prm/lifelong_astar.hpp"

#include <algorithm>
#include <functional>
#include <limits>

namespace amp::roadmap {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr VertexId kNone = std::numeric_limits<VertexId>::max();
const auto kHeapOrder = std::greater<std::tuple<double, double, VertexId>>();  // smallest key on top
}  // namespace

bool LifelongAStar::search(const Roadmap& roadmap, const core::Space& space, std::vector<VertexId>& path) {
  path.clear();
  expanded_ = 0;
  roadmap_ = &roadmap;
  space_ = &space;
  const std::size_t n = roadmap.vertex_count();
  if (!initialized_) {
    initialize(n);
  } else {
    grow(n);
    // The touched vertices' best predecessors may have changed (Fig. 3, lines 17-20: UpdateVertex
    // of every vertex at an end of a changed edge). Sorted and unique: the same repair whatever
    // order the changes came in, each vertex once.
    std::sort(touched_.begin(), touched_.end());
    touched_.erase(std::unique(touched_.begin(), touched_.end()), touched_.end());
    for (const VertexId v : touched_) {
      recompute_rhs(v);
      push_if_inconsistent(v);
    }
  }
  touched_.clear();
  compute_shortest_path();
  return g_[goal_] != kInf && trace_path(path);
}

void LifelongAStar::initialize(std::size_t n) {
  g_.assign(n, kInf);
  rhs_.assign(n, kInf);
  h_.assign(n, -1.0);
  heap_.clear();
  rhs_[start_] = 0.0;
  push_if_inconsistent(start_);
  initialized_ = true;
}

void LifelongAStar::grow(std::size_t n) {
  if (n <= g_.size()) return;
  g_.resize(n, kInf);
  rhs_.resize(n, kInf);
  h_.resize(n, -1.0);
}

double LifelongAStar::heuristic(VertexId v) {
  if (h_[v] < 0.0) h_[v] = space_->distance(roadmap_->state(v), roadmap_->state(goal_));
  return h_[v];
}

LifelongAStar::Key LifelongAStar::key(VertexId v) {
  const double m = std::min(g_[v], rhs_[v]);
  return {m + heuristic(v), m, v};
}

void LifelongAStar::push_if_inconsistent(VertexId v) {
  if (g_[v] == rhs_[v]) return;
  heap_.push_back(key(v));
  std::push_heap(heap_.begin(), heap_.end(), kHeapOrder);
}

// rhs(v) = min over v's neighbours u of g(u) + c(u, v); 0 at the start.
void LifelongAStar::recompute_rhs(VertexId v) {
  if (v == start_) return;
  double best = kInf;
  for (const Edge& e : roadmap_->edges(v)) best = std::min(best, g_[e.to] + e.cost);
  rhs_[v] = best;
}

// An entry is current when its vertex is still inconsistent and its key unchanged; the others were
// overtaken by a later push (every change of g or rhs pushes the vertex again) and are dropped.
bool LifelongAStar::top_is_current() {
  while (!heap_.empty()) {
    const VertexId v = std::get<2>(heap_.front());
    if (g_[v] != rhs_[v] && key(v) == heap_.front()) return true;
    std::pop_heap(heap_.begin(), heap_.end(), kHeapOrder);
    heap_.pop_back();
  }
  return false;
}

// Fig. 3, ComputeShortestPath: expand in key order until the goal is consistent and no inconsistent
// vertex has a smaller key.
void LifelongAStar::compute_shortest_path() {
  while (top_is_current() && (heap_.front() < key(goal_) || g_[goal_] != rhs_[goal_])) {
    std::pop_heap(heap_.begin(), heap_.end(), kHeapOrder);
    const VertexId u = std::get<2>(heap_.back());
    heap_.pop_back();
    ++expanded_;
    if (g_[u] > rhs_[u]) {  // overconsistent: settle u; it can only lower its neighbours' rhs
      g_[u] = rhs_[u];
      for (const Edge& e : roadmap_->edges(u)) {
        if (e.to != start_ && g_[u] + e.cost < rhs_[e.to]) {
          rhs_[e.to] = g_[u] + e.cost;
          push_if_inconsistent(e.to);
        }
      }
    } else {  // underconsistent: u got longer; reopen it and the neighbours whose best way was u
      const double old_g = g_[u];
      g_[u] = kInf;
      recompute_rhs(u);
      push_if_inconsistent(u);
      for (const Edge& e : roadmap_->edges(u)) {
        if (rhs_[e.to] != old_g + e.cost) continue;  // its rhs came from elsewhere: unchanged
        recompute_rhs(e.to);
        push_if_inconsistent(e.to);
      }
    }
  }
}

// From the goal back through the lowest-id neighbour u with g(u) + c(u, v) = g(v): exact equality,
// since g(v) was computed as that very sum. A walk longer than the roadmap (zero-cost edges between
// duplicate states) fails rather than loops.
bool LifelongAStar::trace_path(std::vector<VertexId>& path) const {
  VertexId v = goal_;
  path.push_back(v);
  while (v != start_) {
    if (path.size() > g_.size()) {
      path.clear();
      return false;
    }
    VertexId best = kNone;
    for (const Edge& e : roadmap_->edges(v)) {
      if (g_[e.to] + e.cost == g_[v] && (best == kNone || e.to < best)) best = e.to;
    }
    if (best == kNone) {
      path.clear();
      return false;
    }
    v = best;
    path.push_back(v);
  }
  std::reverse(path.begin(), path.end());
  return true;
}

}  // namespace amp::roadmap
