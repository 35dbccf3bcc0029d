#include "amp/nav/pgcs/portal_graph.hpp"

#include "amp/nav/pgcs/pgcs_explorer.hpp"

namespace amp::nav {

PortalGraph::PortalGraph(const PgcsExplorer& explorer, const EdgeMemory& memory, const EdgeMemory* blocked_now)
    : RouteGraph(explorer.clusters(), memory, blocked_now), explorer_(explorer) {}

Eigen::Vector2d PortalGraph::point(int k) const { return explorer_.node_point(k); }

bool PortalGraph::verified(int a, int b) const { return explorer_.portal(a, b) != nullptr; }

void PortalGraph::more_neighbours(int k, std::vector<int>& out) const {
  for (int j : explorer_.portals().crossed(k)) {
    if (explorer_.portal(k, j) != nullptr) out.push_back(j);
  }
}

std::uint64_t PortalGraph::revision() const { return explorer_.revision(); }

}  // namespace amp::nav
