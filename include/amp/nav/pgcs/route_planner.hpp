#pragma once
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include <Eigen/Core>
#include <boost/heap/d_ary_heap.hpp>

#include "amp/nav/pgcs/edge_memory.hpp"

namespace amp::learn {
class Pgcs;
}

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

// A route on the graph: the start, cluster centres, the target.
struct Route {
  static constexpr int kStart = -1, kTarget = -2;
  std::vector<int> nodes;  // kStart, cluster ids..., kTarget
  std::vector<Eigen::Vector2d> points;
  double cost = 0.0;
  std::size_t expanded = 0;  // search states expanded
  bool empty() const { return nodes.empty(); }
};

// The modified A* of Vlassis, Papakonstantinou & Tsanakas (section 4) on the Delaunay graph of the
// PGCS centres. Start and target join their `attach` nearest centres (the paper's "local paths";
// more than one so that a blocked one leaves others), and straight to each other when the target
// is nearer than any centre. Entering a node w from v, having come from u, costs
//   |vw| + turn_weight * angle(u->v, v->w) + prior_weight * max(0, log(mean prior / pi_w)),
// so smooth routes through often-visited clusters win. The turn term makes the cost depend on the
// previous node: the search runs on directed edges (u, v). The heuristic |v - target| is
// admissible and consistent (every other term is >= 0), so the first expansion of the target is
// optimal. An arrival at a node is not searched on when one already expanded there costs less by
// more than turn_weight times the angle between their headings (no next turn can make up for it),
// which keeps the search exact with far fewer states. Edges the EdgeMemory holds illegal and the
// failed attachments are left out. Beyond the paper, edges the robot has not been seen crossing may
// cost more (unverified_weight), so that routes keep to the ways the robot actually went (through
// doors, not through the walls beside them).
class RoutePlanner {
 public:
  // Throws ParameterError for negative weights or attach < 1.
  explicit RoutePlanner(RouteSettings settings);

  const RouteSettings& settings() const { return settings_; }
  // An optimal route; empty when the graph (less its illegal edges) does not join them.
  // `failed_tolerance`: a failed attachment applies to points within this distance of its point.
  // `verified(a, b)`: whether the edge between clusters a and b is known to be crossed (empty: all);
  // the start's links are unverified too, but for `back`, the cluster the robot has just driven
  // from (it can always return the way it came), which the start joins as well.
  // `where(k)`: the point that stands for cluster k (empty: its centre); NaN leaves k out.
  // `more_neighbours(k, out)` appends edges beyond the Delaunay ones (clusters the robot crossed to).
  // `blocked_now`: edges left out of this plan only, besides the remembered illegal ones.
  // `graph_key`: a non-zero key equal to the previous plan's promises the same clusters, `where`,
  // `verified` and `more_neighbours`, so the nodes' neighbours, lengths, headings and prior
  // penalties found then are reused (the memory, blocked_now, failed attachments, back, start and
  // target are always taken afresh). 0: nothing is reused.
  Route plan(const learn::Pgcs& clusters, const EdgeMemory& memory, const Eigen::Vector2d& start,
             const Eigen::Vector2d& target, std::span<const FailedAttachment> failed, double failed_tolerance,
             const std::function<bool(int, int)>& verified = {},
             const std::function<Eigen::Vector2d(int)>& where = {}, int back = -1,
             const std::function<void(int, std::vector<int>&)>& more_neighbours = {},
             const EdgeMemory* blocked_now = nullptr, std::uint64_t graph_key = 0);

 private:
  // The `attach` nearest triangulated centres to p, without failed ones, into out (local indices).
  void nearest_centres(const learn::Pgcs& clusters, const Eigen::Vector2d& p, std::span<const FailedAttachment> failed,
                       double tolerance, std::vector<int>& out);

  // A directed edge of this plan's graph, v -> w, with what entering w over it costs but the turn.
  struct Arc {
    int to = 0;               // local index
    double cost = 0.0;        // length * (verified ? 1 : 1 + unverified_weight) + penalty of `to`
    double heading = 0.0;     // direction (radians; NaN for a null arc), for the turning angle at `to`
  };
  // A graph edge v -> w as the key's plans share it: what does not change while the key holds.
  struct Neighbour {
    int to = 0;             // local index
    double length = 0.0;
    double heading = 0.0;   // radians; NaN for a null edge
    bool known = true;      // verified, or no unverified weight
  };
  // v's neighbours (Delaunay and more_neighbours, once each), found once per key.
  void find_neighbours(const learn::Pgcs& clusters, int v, const std::function<bool(int, int)>& verified,
                       const std::function<void(int, std::vector<int>&)>& more_neighbours);
  // Appends v's arcs to arcs_ once per plan (illegal edges left out); the search states are arcs.
  void build_arcs(const learn::Pgcs& clusters, const EdgeMemory& memory, const EdgeMemory* blocked_now, int v,
                  const std::function<bool(int, int)>& verified,
                  const std::function<void(int, std::vector<int>&)>& more_neighbours);
  void add_arc(int v, int w, double factor);
  void add_arc(int w, double length, double heading, double factor);
  double penalty(int w);  // the prior penalty of entering local node w, computed once per plan

  RouteSettings settings_;
  std::uint64_t key_ = 0;                    // the graph_key the cached neighbours belong to
  std::vector<int> nbr_begin_, nbr_end_;     // local index -> its neighbours in nbrs_ (begin -1: not found)
  std::vector<Neighbour> nbrs_;
  // Buffers reused across plans (no allocation once grown).
  std::vector<int> local_of_;                // cluster id -> local index
  std::vector<int> ids_;                     // local index -> cluster id
  std::vector<Eigen::Vector2d> points_;      // local index -> position (start, target last)
  std::vector<double> penalty_;              // local index -> prior penalty (NaN: not computed yet)
  std::vector<double> h_;                    // local index -> heuristic (negative: not computed yet)
  const learn::Pgcs* clusters_ = nullptr;    // the clusters of the plan under way
  double log_mean_prior_ = 0.0;
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
  std::vector<int> start_links_, target_links_, neighbours_, scratch_;
  std::vector<std::pair<double, int>> by_distance_;
};

}  // namespace amp::nav
