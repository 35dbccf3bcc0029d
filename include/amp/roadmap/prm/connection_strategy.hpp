#pragma once
#include <vector>

#include "amp/core/state.hpp"
#include "amp/roadmap/neighbors/nearest_neighbors.hpp"
#include "amp/roadmap/roadmap.hpp"

namespace amp::roadmap {

// Chooses which roadmap vertices a new vertex tries to connect to (OMPL's ConnectionStrategy).
// Implementations: KNearestConnection; PRM-C/G/L's "k nearest of each connected component" is
// another. Holds per-run scratch; one per plan() call.
class ConnectionStrategy {
 public:
  virtual ~ConnectionStrategy() = default;
  // Candidates for vertex v (already in `roadmap`) among the vertices add()-ed so far, in the order
  // to try them, into `out` (cleared first).
  virtual void candidates(const Roadmap& roadmap, VertexId v, std::vector<Neighbor>& out) = 0;
  // Makes v a candidate for later vertices.
  virtual void add(VertexId v, const State& s) = 0;
};

}  // namespace amp::roadmap
