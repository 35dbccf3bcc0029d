#pragma once
#include <cstddef>
#include <utility>
#include <vector>

#include "amp/core/space.hpp"
#include "amp/roadmap/roadmap.hpp"

namespace amp::roadmap {

// A* over a roadmap with edge cost = stored cost and heuristic = space.distance to the goal
// (admissible because edge costs are space distances). Ties in f are broken by the smaller vertex
// id, so the same roadmap always gives the same path. Keeps its buffers between searches.
class AStar {
 public:
  // Vertex ids from start to goal inclusive into `path`; false (path empty) when goal is unreachable.
  bool search(const Roadmap& roadmap, const core::Space& space, VertexId start, VertexId goal,
              std::vector<VertexId>& path);
  // Vertices expanded by the last search.
  std::size_t expanded() const { return expanded_; }

 private:
  std::vector<double> g_;
  std::vector<VertexId> parent_;
  std::vector<std::pair<double, VertexId>> heap_;  // (f, vertex), min-heap
  std::size_t expanded_ = 0;
};

}  // namespace amp::roadmap
