#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "amp/nav/pgcs/edge_memory.hpp"

namespace amp::learn {
class Pgcs;
}

namespace amp::nav {

struct RouteSettings {
  double turn_weight = 1.0;   // cost per radian turned between successive edges, in length units
  double prior_weight = 1.0;  // cost per unit of log(mean prior / prior) entering a cluster, in length units
  int attach = 3;             // the start and the target join this many nearest centres
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
// optimal. Edges the EdgeMemory holds and the failed attachments are left out.
class RoutePlanner {
 public:
  // Throws ParameterError for negative weights or attach < 1.
  explicit RoutePlanner(RouteSettings settings);

  const RouteSettings& settings() const { return settings_; }
  // An optimal route; empty when the graph (less its illegal edges) does not join them.
  // `failed_tolerance`: a failed attachment applies to points within this distance of its point.
  Route plan(const learn::Pgcs& clusters, const EdgeMemory& memory, const Eigen::Vector2d& start,
             const Eigen::Vector2d& target, std::span<const FailedAttachment> failed, double failed_tolerance);

 private:
  // The `attach` nearest triangulated centres to p, without failed ones, into out (local indices).
  void nearest_centres(const learn::Pgcs& clusters, const Eigen::Vector2d& p, std::span<const FailedAttachment> failed,
                       double tolerance, std::vector<int>& out);

  RouteSettings settings_;
  // Buffers reused across plans (no allocation once grown).
  std::vector<int> local_of_;                // cluster id -> local index
  std::vector<int> ids_;                     // local index -> cluster id
  std::vector<Eigen::Vector2d> points_;      // local index -> position (start, target last)
  std::vector<double> penalty_;              // local index -> prior penalty
  std::vector<double> g_;                    // state (u, v) -> best cost
  std::vector<int> parent_;                  // state -> previous state
  std::vector<std::uint32_t> stamp_;         // state -> plan number when g_ is valid
  std::vector<std::uint32_t> closed_;       // state -> plan number when expanded
  std::uint32_t generation_ = 0;
  std::vector<std::pair<double, int>> heap_;
  std::vector<int> start_links_, target_links_, neighbours_, scratch_;
  std::vector<std::pair<double, int>> by_distance_;
};

}  // namespace amp::nav
