#pragma once
#include <map>
#include <utility>
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
  // The clusters `a` was ever seen crossing to, ascending (some may be stale: check with find()).
  const std::vector<int>& crossed(int a) const;

 private:
  struct Portal {
    long born_a = 0, born_b = 0;
    long crossings = 0;
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  };
  long memory_;
  std::map<std::pair<int, int>, Portal> portals_;  // (smaller id, larger id)
  std::vector<std::vector<int>> crossed_;           // by id
};

}  // namespace amp::nav
