#pragma once
#include <limits>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "amp/core/state.hpp"
#include "amp/nav/footprint.hpp"

namespace amp::nav {

class NavWorld;

// The reward of the policy-search paper's Sec. 4 and the spread G of its eqs. 5-7.
struct PolicyRewardSettings {
  double c = 1.0;            // cost per metre travelled
  double c_time = 1.0;       // cost per second travelled ("the reward function seeks to minimize travel time")
  double g = 100.0;          // reward for reaching the goal
  double h = 50.0;           // cost per metre travelled with an obstacle closer than the safety range
  double safety = 0.05;      // m: the safety range at rest, beyond the footprint
  // s: the safety range grows by this times the speed: 2.5 control periods of travel (0.1 s each),
  // far beyond the braking distance v^2 / 2a (1.4 cm at 0.26 m/s and 2.5 m/s^2). Twice this slowed
  // the policy through every 0.9 m door of the bundled office (58 s against 47 s over 10 seeds).
  double safety_per_speed = 0.25;
  double sigma = 0.03;       // m: G's lateral standard deviation about the expected path
  double step = 0.02;        // m between the points where the integral of eq. 7 is evaluated
  double v_floor = 0.02;     // m/s: slower waypoints count as this for travel time
  // Throws ParameterError naming the setting for a negative or non-finite value, or step, v_floor
  // <= 0.
  void validate() const;
};

// The value V(pi) of a waypoint policy (eqs. 6-7): the reward integrated along the expected path
// under G. The controller is unbiased (Sec. 3.4), so the expected path is the polyline through the
// waypoints, the robot facing along each segment at a speed interpolated between the waypoints'.
// G is a Gaussian across the path, evaluated at fixed sigma points (3-point Gauss-Hermite: the path
// and +-sqrt(3) sigma beside it, weights 2/3, 1/6, 1/6), so a policy has one value, without
// sampling. The reward per metre at a pose is -c - c_time / v, and -h more when the disc footprint's
// clearance there is below safety + safety_per_speed * v; reaching the goal adds g once. The
// footprint faces along the path: a rectangle's clearance, and so the reward, depends on the
// heading as well as on the speed (a disc's on the speed alone). It memoises
// bounds on the world's distances as it is asked (the answers stay exact), so it is move-only and
// one object is not for concurrent use.
class PolicyValue {
 public:
  // Throws ParameterError for bad settings or radius <= 0.
  PolicyValue(const NavWorld& world, double radius, PolicyRewardSettings settings = {});
  // A footprint checked at the heading of the path (a rectangle is lengthwise along it).
  PolicyValue(const NavWorld& world, const Footprint& footprint, PolicyRewardSettings settings = {});
  ~PolicyValue();
  PolicyValue(PolicyValue&&) noexcept;
  PolicyValue& operator=(PolicyValue&&) noexcept;

  // Value of the segments from waypoint `first` to waypoint `last` (indices into w), without g.
  double segments(const std::vector<State>& w, std::size_t first, std::size_t last) const;
  // Value of the whole policy: every segment, plus g.
  double total(const std::vector<State>& w) const { return (w.size() < 2 ? 0.0 : segments(w, 0, w.size() - 1)) + settings_.g; }
  // Immediate reward per metre at a point at speed v (with G), for eq. 10's insertion test.
  double immediate(const Eigen::Vector2d& p, const Eigen::Vector2d& direction, double v) const;
  // The lowest immediate reward inside segment j (w[j] -> w[j+1]), its point and speed.
  struct Lowest {
    double reward = 0.0;
    Eigen::Vector2d point = Eigen::Vector2d::Zero();
    double v = 0.0;
  };
  Lowest lowest_on_segment(const std::vector<State>& w, std::size_t j) const;

  const PolicyRewardSettings& settings() const { return settings_; }
  double radius() const { return radius_; }  // the footprint's discs'
  const Footprint& footprint() const { return footprint_; }
  const NavWorld& world() const { return *world_; }

 private:
  class DistanceLattice;
  // Bounds on the distance to the obstacles at a point. The distance is 1-Lipschitz, so widened by
  // the distance from that point they bound it anywhere.
  struct DistanceBounds {
    Eigen::Vector2d at = Eigen::Vector2d::Zero();
    double lower = -1.0;  // < 0: nothing known
    double upper = std::numeric_limits<double>::infinity();
  };
  enum class Side { kClear, kWithin, kUnknown };
  // Whether b proves every point within `spread` of p clear of the safety range `range`, or within it.
  Side side_of(const DistanceBounds& b, const Eigen::Vector2d& p, double spread, double range) const;
  // Whether the disc's clearance at q is below `range`: exactly NavWorld::clearance(q, r) < range.
  bool within_range(const Eigen::Vector2d& q, double range) const;
  // The reward per metre at p moving across `side` (a unit normal, or zero) at speed v. `around`
  // carries bounds from one point to the next along a path, and most points need nothing more.
  double reward_at(const Eigen::Vector2d& p, const Eigen::Vector2d& side, double v, DistanceBounds& around) const;

  const NavWorld* world_;
  Footprint footprint_;
  double radius_;
  PolicyRewardSettings settings_;
  // Bounds on the distance to the obstacles, filled as the value is asked for (policy_value.cpp).
  std::unique_ptr<DistanceLattice> lattice_;
};

}  // namespace amp::nav
