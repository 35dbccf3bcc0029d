#pragma once
#include <cstdint>
#include <functional>
#include <span>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <boost/heap/d_ary_heap.hpp>

#include "amp/nav/pgcs/edge_memory.hpp"
#include "amp/nav/pgcs/route_graph.hpp"

namespace amp::nav {

struct RouteSettings {
  double turn_weight = 1.0;   // cost per radian turned between successive edges, in length units
  double prior_weight = 1.0;  // cost per unit of log(mean prior / prior) entering a cluster, in length units
  int attach = 3;             // the start and the target join this many nearest centres
  // Extra cost per length of an edge between clusters that is not `verified` (the robot was never
  // seen crossing between them): length * (1 + unverified_weight). 0: the paper's A*.
  double unverified_weight = 0.0;
  // Extra cost per length of an edge blocked before but not yet illegal (EdgeMemory's strikes > 1):
  // length * (1 + suspect_weight), so that it is tried again only when nothing else joins.
  double suspect_weight = 100.0;
};

// A leg end that failed for this query: the robot, near `point`, could not drive to (or from)
// `cluster`'s centre; cluster Route::kTarget: straight from `point` to the target.
struct FailedAttachment {
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  int cluster = -1;
};

// A route on the graph: the start, the clusters' points, the target.
struct Route {
  static constexpr int kStart = -1, kTarget = -2;
  std::vector<int> nodes;  // kStart, cluster ids..., kTarget
  std::vector<Eigen::Vector2d> points;
  double cost = 0.0;
  std::size_t expanded = 0;  // search states expanded
  bool empty() const { return nodes.empty(); }
};

// How one plan's start and target join the graph, besides each joining its `attach` nearest nodes.
struct RouteEnds {
  // Leg ends that failed in this query; one applies to points within `tolerance` of its point.
  std::span<const FailedAttachment> failed;
  double tolerance = 0.0;
  // The cluster the robot has just driven from (-1: none): the start joins it too, as a verified
  // edge (the robot can always return the way it came).
  int back = -1;
};

// The modified A* of Vlassis, Papakonstantinou & Tsanakas (section 4) on a RouteGraph (the
// Delaunay graph of the PGCS centres, with any edges the graph adds). Start and target join their
// `attach` nearest nodes (the paper's "local paths"; more than one so that a blocked one leaves
// others), and straight to each other when the target is nearer than any node. Entering a node w
// from v, having come from u, costs
//   |vw| + turn_weight * angle(u->v, v->w) + prior_weight * max(0, log(mean prior / pi_w)),
// so smooth routes through often-visited clusters win. The turn term makes the cost depend on the
// previous node: the search runs on directed edges (u, v). The heuristic |v - target| is
// admissible and consistent (every other term is >= 0), so the first expansion of the target is
// optimal. An arrival at a node is not searched on when one already expanded there costs less by
// more than turn_weight times the angle between their headings (no next turn can make up for it),
// which keeps the search exact with far fewer states. Edges the graph's memories hold illegal and
// the failed attachments are left out. Beyond the paper, edges the robot has not been seen crossing
// may cost more (unverified_weight), so that routes keep to the ways the robot actually went
// (through doors, not through the walls beside them).
class RoutePlanner {
 public:
  // Throws ParameterError for negative weights or attach < 1.
  explicit RoutePlanner(RouteSettings settings);

  const RouteSettings& settings() const { return settings_; }
  // An optimal route; empty when the graph (less its illegal edges) does not join them. The start's
  // links are unverified, but for `ends.back`.
  Route plan(RouteGraph& graph, const Eigen::Vector2d& start, const Eigen::Vector2d& target, const RouteEnds& ends = {});

 private:
  // A directed edge of this plan's graph, v -> w, with what entering w over it costs but the turn.
  struct Arc {
    int to = 0;               // local index
    double cost = 0.0;        // length * (verified ? 1 : 1 + unverified_weight) + penalty of `to`
    double heading = 0.0;     // direction (radians; NaN for a null arc), for the turning angle at `to`
  };
  // Local indices: the graph's nodes, then the start (s_) and the target (s_ + 1).
  const Eigen::Vector2d& point(int v) const;
  // Per-plan state reset, for `graph` brought up to date.
  void begin(RouteGraph& graph, const Eigen::Vector2d& start, const Eigen::Vector2d& target);
  // The start's arcs and the nodes that join the target.
  void join_ends(const RouteEnds& ends);
  // The `attach` nearest triangulated nodes to p, without failed ones, into out (local indices).
  void nearest_nodes(const Eigen::Vector2d& p, const RouteEnds& ends, std::vector<int>& out);
  // The A* over arcs: the arc that reaches the target first, or -1; counts expansions.
  int search(std::size_t& expanded);
  // Appends v's arcs to arcs_ once per plan (illegal edges left out); the search states are arcs.
  void build_arcs(int v);
  void add_arc(int v, int w, double factor);
  void add_arc(int w, double length, double heading, double factor);
  double penalty(int w) const;  // the prior penalty of entering local node w
  double h(int v);              // the straight distance to the target, once per node and plan
  // Whether an arrival at v with this heading and cost is dominated by one expanded there.
  bool dominated(int v, double heading, double c) const;
  void relax(int from_arc, int a, double c);
  void grow();  // per-arc state for arcs built since the last call
  void trace_back(int goal_arc, Route& route);

  RouteSettings settings_;
  RouteGraph* graph_ = nullptr;              // the graph of the plan under way
  int s_ = 0;                                // the start's local index (the graph's size)
  Eigen::Vector2d ends_[2];                  // the start and the target of the plan under way
  // Buffers reused across plans (no allocation once grown).
  std::vector<double> h_;                    // local index -> heuristic (negative: not computed yet)
  std::vector<int> arcs_begin_, arcs_end_;   // local index -> its arcs in arcs_ (begin -1: not built)
  std::vector<std::uint8_t> links_target_;   // local index -> joins the target
  std::vector<Arc> arcs_;
  std::vector<double> g_;                    // arc -> best cost of arriving over it
  std::vector<int> parent_;                  // arc -> the arc before it (-1: from the start)
  std::vector<std::uint8_t> closed_;         // arc -> expanded
  std::vector<double> best_in_;              // local index -> cheapest expanded arrival
  std::vector<int> in_head_, in_next_;       // local index -> its expanded arrivals, listed through arcs
  // (f, arc), least first; 4-ary: fewer levels than a binary heap for the same pops.
  boost::heap::d_ary_heap<std::pair<double, int>, boost::heap::arity<4>,
                          boost::heap::compare<std::greater<std::pair<double, int>>>>
      heap_;
  std::vector<int> start_links_, target_links_, scratch_;
  std::vector<std::pair<double, int>> by_distance_;
};

}  // namespace amp::nav
