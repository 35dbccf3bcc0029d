#pragma once
#include <cstdint>
#include <vector>

#include "amp/nav/pgcs/route_graph.hpp"

namespace amp::nav {

class PgcsExplorer;

// The learned graph as the explorer crossed it: each cluster stands at its node point (its
// exemplar), an edge is verified when the explorer's portal for it is known (EdgePortals), and
// clusters the explorer crossed between are joined even when their centres are no longer Delaunay
// neighbours. It follows the explorer: whatever the explorer learns or drops, the next plan sees.
class PortalGraph final : public RouteGraph {
 public:
  PortalGraph(const PgcsExplorer& explorer, const EdgeMemory& memory, const EdgeMemory* blocked_now = nullptr);

 protected:
  Eigen::Vector2d point(int k) const override;
  bool verified(int a, int b) const override;
  void more_neighbours(int k, std::vector<int>& out) const override;
  std::uint64_t revision() const override;

 private:
  const PgcsExplorer& explorer_;
};

}  // namespace amp::nav
