#pragma once
#include <memory>
#include <vector>

#include "amp/core/counters.hpp"
#include "amp/core/space.hpp"
#include "amp/roadmap/neighbors/nearest_neighbors.hpp"

namespace amp::roadmap {

// Exact k nearest neighbours with one dynamic KD-tree (dynamic_kd_tree.hpp: bucket insertion,
// scapegoat rebalancing, full rebuild when the size doubles, so insertion is amortised O(log n) on
// random orders), searched by branch and bound with a lower bound of space.distance() over each
// node's box (kd_bounds.hpp): per block for SE3 (translation + rotation angle, q and -q), through
// the space's Euclidean embedding otherwise.
//
// Every state reached is ranked by its TRUE distance and the tree is pruned at the current k-th
// true distance: a state never reached has a lower bound, hence a true distance, beyond it. One
// pass gives exactly the brute-force answer (ties by index included).
class KdTreeNeighbors final : public NearestNeighbors {
 public:
  // `counters` may be null; space and counters must outlive this object.
  explicit KdTreeNeighbors(const core::Space& space, core::Counters* counters = nullptr);
  ~KdTreeNeighbors() override;
  KdTreeNeighbors(const KdTreeNeighbors&) = delete;
  KdTreeNeighbors& operator=(const KdTreeNeighbors&) = delete;

  void add(std::size_t index, const State& s) override;
  void k_nearest(const State& q, std::size_t k, std::vector<Neighbor>& out) const override;
  std::size_t size() const override;
  void reserve(std::size_t n) override;

  // True distances the last query computed (how hard the embedding made it; n for brute force).
  std::size_t last_distance_evaluations() const;

  struct Impl;  // the tree, per bound policy (defined in the .cpp)

 private:
  core::Counters* counters_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace amp::roadmap
