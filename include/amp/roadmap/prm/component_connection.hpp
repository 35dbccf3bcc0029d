#pragma once
#include <cstddef>
#include <vector>

#include "amp/core/space.hpp"
#include "amp/roadmap/prm/connection_strategy.hpp"

namespace amp::roadmap {

// Up to k nearest vertices of *each* connected component (Isto 2003), nearest
// first over all components (ties by lower id). With PrmSettings::skip_same_component the PRM stops
// trying a component once the new vertex has joined it, so k bounds the attempts per component.
// A linear scan per query: O(S log S) for S vertices, small beside the A* searches it feeds.
class ComponentNearestConnection final : public ConnectionStrategy {
 public:
  ComponentNearestConnection(const core::Space& space, std::size_t k);
  void candidates(const Roadmap& roadmap, VertexId v, std::vector<Neighbor>& out) override;
  void add(VertexId v, const State& s) override;

 private:
  struct Entry {
    double distance;
    VertexId component;
    VertexId id;
  };
  const core::Space* space_;
  std::size_t k_;
  std::vector<VertexId> added_;
  std::vector<Entry> scratch_;
};

}  // namespace amp::roadmap
