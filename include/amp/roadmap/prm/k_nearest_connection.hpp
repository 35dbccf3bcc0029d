#pragma once
#include <cstddef>
#include <memory>

#include "amp/roadmap/prm/connection_strategy.hpp"
#include "amp/roadmap/neighbors/nearest_neighbors.hpp"

namespace amp::roadmap {

// The k nearest vertices, nearest first (ties by lower id).
class KNearestConnection final : public ConnectionStrategy {
 public:
  KNearestConnection(std::unique_ptr<NearestNeighbors> neighbors, std::size_t k)
      : neighbors_(std::move(neighbors)), k_(k) {}

  void candidates(const Roadmap& roadmap, VertexId v, std::vector<Neighbor>& out) override {
    neighbors_->k_nearest(roadmap.state(v), k_, out);
  }
  void add(VertexId v, const State& s) override { neighbors_->add(v, s); }

  NearestNeighbors& neighbors() { return *neighbors_; }

 private:
  std::unique_ptr<NearestNeighbors> neighbors_;
  std::size_t k_;
};

}  // namespace amp::roadmap
