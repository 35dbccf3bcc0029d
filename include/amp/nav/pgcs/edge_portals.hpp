#pragma once
#include <cstdint>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

namespace amp::nav {

// Where the exploring robot crossed from one cluster's Voronoi cell into another's: whenever its
// nearest centre changes between two steps, the midpoint of the two positions is a crossing of that pair,
// and each pair keeps the running mean of its crossings (over at most `memory` of them, so that it
// follows clusters that drift). Driving a graph edge through its portal follows where the robot
// really went (a door) where the straight segment between the centres may clip a door frame. This
// goes beyond Vlassis et al., whose edges are straight; PgcsRunSettings::portals turns it off.
// Clusters are named by id and birth step, so a reused id never inherits an old portal.
class EdgePortals {
 public:
  explicit EdgePortals(long memory) : memory_(memory) {}

  void observe(int a, long born_a, int b, long born_b, const Eigen::Vector2d& crossing);
  // The portal of the pair, or null when the robot never crossed between these two clusters.
  const Eigen::Vector2d* find(int a, long born_a, int b, long born_b) const;
  std::size_t size() const { return portals_.size(); }
  // The clusters `a` was seen crossing to since it was last forgotten, ascending (a partner reborn
  // under the same id may still be listed: check with find()).
  const std::vector<int>& crossed(int a) const;
  // Drops every pair of cluster `a` (deleted, or its id about to be reused), so that the lists
  // crossed() returns hold live pairs only and stay as short as the cell's true neighbourhood.
  void forget(int a);
  // Drops the pair a-b (its portal proved undrivable).
  void drop(int a, int b);

 private:
  struct Portal {
    long born_a = 0, born_b = 0;
    long crossings = 0;
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  };
  static std::uint64_t key(int a, int b) {  // a < b
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
  }
  long memory_;
  std::unordered_map<std::uint64_t, Portal> portals_;  // by key(smaller id, larger id); looked up, never iterated
  std::vector<std::vector<int>> crossed_;           // by id
};

}  // namespace amp::nav
