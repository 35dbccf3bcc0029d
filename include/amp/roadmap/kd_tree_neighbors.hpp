#pragma once
#include <memory>
#include <vector>

#include "amp/core/counters.hpp"
#include "amp/core/space.hpp"
#include "amp/roadmap/nearest_neighbors.hpp"

namespace amp::roadmap {

// Exact k nearest neighbours with a nanoflann dynamic KD-tree (a logarithmic family of static trees,
// so insertion is amortised polylogarithmic) over core::Space::embed().
//
// The embedding's Euclidean distance is only a lower bound of space.distance() (angles embed as
// chords, SE3 orientations as q and -q). Rather than retrieving K' embedded candidates and growing
// K' until the bound certifies them, the search ranks every state it reaches by its TRUE distance and
// prunes the tree at the current k-th true distance (branch and bound): a state never reached has
// embedded, hence true, distance beyond that bound. One pass per embedding variant, sharing the
// bound, gives exactly the brute-force answer (ties by index included).
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

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace amp::roadmap
