#pragma once
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "amp/nav/pgcs/route_graph.hpp"

namespace amp::nav {

class PgcsExplorer;
class TraceCorridor;

// The learned graph as the robot's trace joins it (PgcsRunSettings::trace_legs): two clusters are
// linked when the trace holds cells of theirs side by side (on the corridor's raster, each cell
// labelled with its nearest centre). Links are the verified edges, and are edges even where the
// centres are no longer Delaunay neighbours; each cluster stands at its node point. The links hold
// from one link() to the next, so that a query plans on one graph while its driving marks the trace.
class TraceGraph final : public RouteGraph {
 public:
  TraceGraph(const PgcsExplorer& explorer, const TraceCorridor& corridor, const EdgeMemory& memory,
             const EdgeMemory* blocked_now = nullptr);

  // Makes the links afresh when the clusters or the trace changed since they were made.
  void link();
  bool linked(int a, int b) const;
  // Appends the clusters k is linked to (none for k < 0).
  void append_links(int k, std::vector<int>& out) const;
  // The cluster whose cell holds raster cell `cell` (-1 for cell < 0), cached while the clusters
  // stand still.
  int cell_label(int cell);
  // The cluster whose cell holds p, when it has a point to drive to (else -1).
  int home(const Eigen::Vector2d& p);

 protected:
  Eigen::Vector2d point(int k) const override;
  bool verified(int a, int b) const override { return linked(a, b); }
  void more_neighbours(int k, std::vector<int>& out) const override { append_links(k, out); }
  std::uint64_t revision() const override;

 private:
  const PgcsExplorer& explorer_;
  const TraceCorridor& corridor_;
  std::vector<int> label_;  // per raster cell: the nearest cluster (-2: not yet asked), for label_step_
  long label_step_ = -1;
  // By cluster id: the clusters linked to it (sorted), for the clusters of links_step_ and the trace
  // of links_version_.
  std::vector<std::vector<int>> links_;
  long links_step_ = -1;
  std::uint64_t links_version_ = 0;
  std::uint64_t links_made_ = 0;  // link() calls that made the links afresh
};

}  // namespace amp::nav
