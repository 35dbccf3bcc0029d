#pragma once
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "amp/world/planar_robot.hpp"
#include "amp/world/planar_world.hpp"
#include "amp/world/validity_checker.hpp"

namespace amp::world {

// How a planar robot must stay inside the world bounds.
enum class PlanarBoundsCheck {
  kWholeRobot,      // every robot shape inside the closed box: our YAML problems
  kReferencePoint,  // only the reference point: OMPL.app's rule for its .cfg problems
};

// Exact validity checker for a planar robot in a PlanarWorld. Per robot shape: grid cells under
// its bounding box give candidate edges and circles; an edge whose line leaves every robot vertex
// on one side is rejected before any segment test; containment either way is settled by one point
// (robot vertex in obstacle via the grid parity test, obstacle vertex in robot). Touching counts as
// collision. The robot must lie inside the world bounds (closed box). Arms and linkages also test
// non-adjacent links against each other. Scratch is sized in the constructor: checks never allocate.
class PlanarChecker final : public ValidityChecker {
 public:
  PlanarChecker(std::shared_ptr<const PlanarWorld> world, PlanarRobot robot, core::Counters& counters,
                PlanarBoundsCheck bounds_check = PlanarBoundsCheck::kWholeRobot);

  const PlanarWorld& world() const { return *world_; }
  const PlanarRobot& robot() const { return robot_; }

 private:
  struct BodyPolygon {
    int link = 0;
    int first = 0;  // into local_ / placed_
    int count = 0;
  };
  struct BodyCircle {
    int link = 0;
    Eigen::Vector2d center = Eigen::Vector2d::Zero();  // link frame
    double radius = 0.0;
  };
  struct LinkRange {
    int polygon_begin = 0, polygon_end = 0, circle_begin = 0, circle_end = 0;
  };

  // Throws ParameterError when s has the wrong dimension (a programming error upstream).
  bool check(const State& s) const override;
  // Exact distance to the nearest obstacle shape (bounds are not obstacles); 0 when s is not valid;
  // +infinity in a world without obstacles.
  Clearance compute_clearance(const State& s) const override;
  // min(obstacle distance, distance to leave the bounds, half the distance between non-adjacent
  // links); planar_certification.cpp.
  double compute_free_radius(const State& s) const override;
  // |dxy| + reach * |dtheta| for rigid bodies; per joint, its angle change times the reach of the
  // links it turns, for arms and linkages.
  double compute_motion_bound(const State& a, const State& b) const override;
  double bounds_margin() const;
  // The reference point of the robot as place() last put it.
  Eigen::Vector2d reference_point_placed() const;
  double self_distance() const;

  // Places every robot shape in the world frame (placed_, circle_centers_, boxes). False for a
  // non-finite state.
  bool place(const State& s) const;
  bool inside_bounds() const;
  template <class OnEdge, class OnCircle>
  bool any_near(const Eigen::AlignedBox2d& box, OnEdge&& on_edge, OnCircle&& on_circle) const;
  bool polygon_hits_obstacles(int k) const;
  bool circle_hits_obstacles(int k) const;
  bool self_collides() const;
  std::span<const Eigen::Vector2d> placed(int k) const {
    return {placed_.data() + polygons_[k].first, static_cast<std::size_t>(polygons_[k].count)};
  }
  std::uint32_t next_stamp() const;
  void nearest_to_polygon(int k, double& best_sq, Clearance& out) const;
  void nearest_to_circle(int k, double& best, Clearance& out) const;

  std::shared_ptr<const PlanarWorld> world_;
  PlanarRobot robot_;
  PlanarBoundsCheck bounds_check_;
  // joint_reach_[j]: the farthest any point of links j, j+1, ... lies from joint j (link j's origin).
  std::vector<double> joint_reach_;
  std::vector<BodyPolygon> polygons_;
  std::vector<Eigen::Vector2d> local_;
  std::vector<BodyCircle> circles_;
  std::vector<LinkRange> link_ranges_;
  std::vector<int> polygon_first_edge_;  // world edges of obstacle polygon p start here

  mutable std::vector<Pose2> poses_;
  mutable std::vector<Eigen::Vector2d> placed_;
  mutable std::vector<Eigen::AlignedBox2d> polygon_boxes_;
  mutable std::vector<Eigen::Vector2d> circle_centers_;
  mutable std::vector<Eigen::AlignedBox2d> link_boxes_;
  mutable std::vector<std::uint32_t> edge_stamp_, polygon_stamp_, circle_stamp_;
  mutable std::uint32_t stamp_ = 0;
  mutable std::vector<int> parity_scratch_;
};

}  // namespace amp::world
