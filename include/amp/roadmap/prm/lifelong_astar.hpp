#pragma once
#include <cstddef>
#include <tuple>
#include <vector>

#include "amp/core/space.hpp"
#include "amp/roadmap/roadmap.hpp"

namespace amp::roadmap {

// Lifelong Planning A* (Koenig, Likhachev & Furcy 2004, "Lifelong Planning A*", Fig. 3) between two
// fixed vertices of a roadmap that changes between searches: vertices and edges are added, edges
// removed. Each search repairs the previous one instead of starting again: only the vertices whose
// shortest distance from the start the changes can alter are expanded. Lazy PRM (Bohlin & Kavraki
// 2000) searches its roadmap again after every edge it removes; from scratch that is O(E log V) each
// time, over tens of thousands of edges (docs/lazy-prm.md).
//
// The caller reports every vertex whose edge list changed (touch) before the next search. Edge
// costs are the stored ones and the heuristic the space's distance to the goal, admissible and
// consistent because every cost is a space distance. The path is the same shortest path for the
// same sequence of roadmap changes: heap ties are broken by vertex id, and the path is traced back
// from the goal through the lowest-id predecessor that gives its distance.
class LifelongAStar {
 public:
  LifelongAStar(VertexId start, VertexId goal) : start_(start), goal_(goal) {}

  // v's edges changed since the last search (v new, an edge of v added or removed). Before the
  // first search nothing needs telling: it reads the whole roadmap.
  void touch(VertexId v) {
    if (initialized_) touched_.push_back(v);
  }
  // Vertex ids from start to goal inclusive into `path`; false (path empty) when goal is unreachable.
  bool search(const Roadmap& roadmap, const core::Space& space, std::vector<VertexId>& path);
  // Vertices expanded by the last search (each expansion settles or reopens one vertex).
  std::size_t expanded() const { return expanded_; }

 private:
  using Key = std::tuple<double, double, VertexId>;  // (min(g, rhs) + h, min(g, rhs), vertex)

  void initialize(std::size_t n);
  void grow(std::size_t n);
  double heuristic(VertexId v);
  Key key(VertexId v);
  void push_if_inconsistent(VertexId v);
  void recompute_rhs(VertexId v);
  void compute_shortest_path();
  bool top_is_current();
  bool trace_path(std::vector<VertexId>& path) const;

  VertexId start_;
  VertexId goal_;
  const Roadmap* roadmap_ = nullptr;
  const core::Space* space_ = nullptr;
  bool initialized_ = false;
  std::vector<double> g_;
  std::vector<double> rhs_;
  std::vector<double> h_;  // cached distance to the goal; negative: not computed yet
  std::vector<Key> heap_;  // min-heap; stale entries are skipped when they come to the top
  std::vector<VertexId> touched_;
  std::size_t expanded_ = 0;
};

}  // namespace amp::roadmap
