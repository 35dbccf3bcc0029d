#pragma once
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>

namespace amp::learn {
class Pgcs;
}

namespace amp::nav {

class EdgeMemory;

// The graph RoutePlanner searches (Vlassis, Papakonstantinou & Tsanakas, section 4): the live PGCS
// clusters as nodes, each standing at a point, joined by their Delaunay edges and any more an
// implementation adds. An edge is verified when the robot is known to cross it; the memories leave
// edges out. An implementation answers point(), verified() and more_neighbours(), and revision()
// changes whenever any of them may answer differently. What plans derive from these answers (the
// nodes' local indices and points, prior excesses, neighbours with lengths and headings) is kept
// until the revision or the number of clusters changes, so plans on a graph that stands still
// share that work and no caller has to say when it may.
class RouteGraph {
 public:
  // An edge from a node, as the cache keeps it.
  struct Neighbour {
    int to = 0;             // local index
    double length = 0.0;
    double heading = 0.0;   // radians; NaN for a null edge
    bool verified = true;
  };

  // `memory`: edges blocked before (illegal ones are left out, suspects cost more); `blocked_now`:
  // more edges left out (null: none). Plans read both afresh. `clusters` and both memories must
  // outlive the graph.
  RouteGraph(const learn::Pgcs& clusters, const EdgeMemory& memory, const EdgeMemory* blocked_now = nullptr);
  virtual ~RouteGraph();
  RouteGraph(const RouteGraph&) = delete;
  RouteGraph& operator=(const RouteGraph&) = delete;

  const learn::Pgcs& clusters() const { return clusters_; }
  const EdgeMemory& memory() const { return memory_; }
  const EdgeMemory* blocked_now() const { return blocked_now_; }

  // The cache, as a plan reads it: refresh() first. Nodes have local indices 0 .. size() - 1, in the
  // order of clusters().ids().
  void refresh();
  int size() const { return static_cast<int>(ids_.size()); }
  int id(int v) const { return ids_[static_cast<std::size_t>(v)]; }
  int local(int id) const;  // -1: no node of this graph
  const Eigen::Vector2d& at(int v) const { return points_[static_cast<std::size_t>(v)]; }  // NaN: left out
  // max(0, log(mean prior / prior)) of node v (+inf for a prior of 0), taken once per refresh (a log
  // per cluster per plan cost more than the search). Inline: a plan asks once per arc.
  double prior_excess(int v) {
    const double e = excess_[static_cast<std::size_t>(v)];
    return std::isnan(e) ? take_prior_excess(v) : e;
  }
  // v's neighbours: Delaunay and more, once each, without nodes left out; found once per refresh.
  std::span<const Neighbour> neighbours(int v) {
    if (nbr_begin_[static_cast<std::size_t>(v)] < 0) find_neighbours(v);
    const auto begin = static_cast<std::size_t>(nbr_begin_[static_cast<std::size_t>(v)]);
    return {nbrs_.data() + begin, static_cast<std::size_t>(nbr_end_[static_cast<std::size_t>(v)]) - begin};
  }

 protected:
  // The point that stands for cluster k; NaN leaves k out of routes.
  virtual Eigen::Vector2d point(int k) const = 0;
  // Whether the robot is known to cross between clusters a and b.
  virtual bool verified(int a, int b) const = 0;
  // Appends k's edges beyond the Delaunay ones.
  virtual void more_neighbours(int k, std::vector<int>& out) const = 0;
  // Changes whenever point, verified or more_neighbours may answer differently; by default the
  // clusters' steps (the clusters move only when they learn).
  virtual std::uint64_t revision() const;

 private:
  double take_prior_excess(int v);
  void find_neighbours(int v);

  const learn::Pgcs& clusters_;
  const EdgeMemory& memory_;
  const EdgeMemory* blocked_now_;
  bool fresh_ = false;
  std::uint64_t revision_ = 0;               // revision() when the cache was made
  std::vector<int> ids_;                     // local index -> cluster id
  std::vector<int> local_of_;                // cluster id -> local index (-1: none)
  std::vector<Eigen::Vector2d> points_;      // local index -> point()
  double log_mean_prior_ = 0.0;
  std::vector<double> excess_;               // local index -> prior excess (NaN: not taken yet)
  std::vector<int> nbr_begin_, nbr_end_;     // local index -> its neighbours in nbrs_ (begin -1: not found)
  std::vector<Neighbour> nbrs_;
  std::vector<int> scratch_;
};

// The paper's graph: the clusters' centres joined by their Delaunay edges, each edge verified.
class CentreGraph final : public RouteGraph {
 public:
  using RouteGraph::RouteGraph;

 protected:
  Eigen::Vector2d point(int k) const override;
  bool verified(int, int) const override { return true; }
  void more_neighbours(int, std::vector<int>&) const override {}
};

}  // namespace amp::nav
