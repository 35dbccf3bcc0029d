#pragma once
#include <array>
#include <memory>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "amp/core/state.hpp"
#include "amp/world/spatial_world.hpp"

namespace amp::world {

namespace detail {
struct RobotGeometry;  // FCL geometries of the parts, built once, shared by all checkers
}

// The 5-DOF SCARA-type arm. State (base yaw psi, slide z, shoulder t1, elbow t2, wrist yaw phi):
//   column   : vertical cylinder (radius link_radius, height column_height) standing on `base`,
//              turned by psi about the vertical axis;
//   upper arm: box l1 x 2r x 2r leaving the column at height base.z + z, along yaw psi + t1;
//   forearm  : box l2 x 2r x 2r from the elbow, same height, along yaw psi + t1 + t2;
//   wrist    : vertical cylinder (radius r, length wrist_length) hanging below the forearm's end,
//              yaw psi + t1 + t2 + phi;
//   tool     : `tool` boxes in the flange frame (origin wrist_length below the forearm's end, x
//              along the wrist yaw, z up); the tool tip (reference point) is `tip` in that frame.
// Adjacent links touch by design; self-collision is checked between non-adjacent links only.
struct ScaraParams {
  Eigen::Vector3d base = Eigen::Vector3d::Zero();
  double column_height = 1.0;
  double upper_arm = 0.5;   // l1
  double forearm = 0.4;     // l2
  double link_radius = 0.05;
  double wrist_length = 0.1;
  double slide_lo = 0.2, slide_hi = 0.9;  // z range of the arm above the base, within the column
  // Limits of base yaw, shoulder, elbow, wrist yaw (revolute, ranges up to 2 pi).
  std::array<std::pair<double, double>, 4> limits{{{-3.1, 3.1}, {-2.5, 2.5}, {-2.6, 2.6}, {-3.1, 3.1}}};
  std::vector<Solid> tool;  // boxes in the flange frame
  Eigen::Vector3d tip = Eigen::Vector3d::Zero();

  // Throws ParameterError for non-positive lengths, empty ranges or a slide leaving the column.
  void validate() const;
};

// A robot in a 3-D world: rigid links, each made of solids placed in the link's frame.
//   rigid:  one link, state se3 (x y z qx qy qz qw), reference point = body origin;
//   sphere: one sphere link, state (x y z);
//   scara:  five links (column, upper arm, forearm, wrist, tool), state as in ScaraParams.
class SpatialRobot {
 public:
  enum class Kind { kRigid, kSphere, kScara };
  static constexpr int kMaxLinks = 5;

  static SpatialRobot rigid(std::vector<Solid> body);
  static SpatialRobot sphere(double radius);
  static SpatialRobot scara(ScaraParams params);

  Kind kind() const { return kind_; }
  int link_count() const { return static_cast<int>(links_.size()); }
  // Solids of link i in that link's frame.
  const std::vector<Solid>& link_solids(int i) const { return links_[static_cast<std::size_t>(i)]; }
  const ScaraParams& scara_params() const { return scara_; }

  // Forward kinematics: the world pose of each link's frame (`out` holds link_count() poses).
  void link_poses(const State& s, Eigen::Isometry3d* out) const;
  // Reference point: body origin (rigid, sphere) or tool tip (scara).
  Eigen::Vector3d reference_point(const State& s) const;
  // Pairs of links checked for self-collision (non-adjacent links of the arm; none otherwise).
  const std::vector<std::pair<int, int>>& self_pairs() const { return self_pairs_; }

  // Farthest robot point from the origin of link 0's frame over all configurations (scara:
  // reach from the column axis), and the smallest side of the robot's body-frame bounds.
  double radius() const { return radius_; }
  double min_diameter() const { return min_diameter_; }

  const detail::RobotGeometry& geometry() const { return *geometry_; }

 private:
  SpatialRobot(Kind kind, std::vector<std::vector<Solid>> links);

  Kind kind_;
  std::vector<std::vector<Solid>> links_;
  ScaraParams scara_;
  std::vector<std::pair<int, int>> self_pairs_;
  double radius_ = 0.0;
  double min_diameter_ = 0.0;
  std::shared_ptr<const detail::RobotGeometry> geometry_;
};

}  // namespace amp::world
