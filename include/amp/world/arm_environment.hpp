#pragma once
// An arm (URDF + SRDF planning group) in a MoveIt scene: the Environment that `amp plan --urdf ...`
// plans in. Collision checking is FCL on the links' collision geometry, as MoveIt does; self-
// collision between every pair of links but the SRDF's disabled pairs and the scene's allowed ones.
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "amp/world/arm_kinematics.hpp"
#include "amp/world/environment.hpp"
#include "amp/world/moveit_files.hpp"
#include "amp/world/spatial_world.hpp"

namespace amp::world {

namespace detail {
struct ArmGeometry;  // FCL geometry of the links, built once, shared by every checker
struct ArmMotionCoefficients;  // per-part and per-pair joint-step bounds
}

// The robot side: kinematics, which pairs are checked, and the per-joint motion radii that bound
// how far any robot point moves for a joint step (docs/arms.md, "Certification").
class ArmRobot {
 public:
  // `geometry`: make_arm_geometry(kinematics.model()), shared by every problem of the robot.
  // `disabled`: link pairs never checked (the SRDF's disabled_collisions and the scene's allowed
  // pairs of two links). A pair naming a link the model lacks is ignored, as MoveIt ignores it.
  ArmRobot(ArmKinematics kinematics, std::shared_ptr<const detail::ArmGeometry> geometry,
           const std::vector<std::pair<std::string, std::string>>& disabled);

  const ArmKinematics& kinematics() const { return kinematics_; }
  const ArmModel& model() const { return kinematics_.model(); }
  // Link pairs checked against each other (both with geometry, not disabled).
  const std::vector<std::pair<int, int>>& self_pairs() const { return self_pairs_; }
  // For group joint k: a bound on the distance from joint k's axis of any point of the links it
  // moves (1 for a prismatic joint: the slide itself), mimic followers included.
  const std::vector<double>& motion_radii() const { return motion_radii_; }
  // Largest distance of a robot point from the root frame's origin, over all configurations.
  double reach() const { return reach_; }
  // Smallest side of any link solid's bounds (the Gaussian sampler's distance).
  double min_diameter() const { return min_diameter_; }
  const detail::ArmGeometry& geometry() const { return *geometry_; }
  // Part index pairs (into geometry().parts) checked for self-collision.
  const std::vector<std::pair<int, int>>& self_part_pairs() const { return self_part_pairs_; }
  // How far each part, and each self pair relative to each other, moves per joint step.
  const detail::ArmMotionCoefficients& motion_coefficients() const { return *coefficients_; }
  // The same, read one at a time: parts are the links' collision solids in link order.
  std::size_t part_count() const;
  int part_link(std::size_t part) const;
  // Distance travelled per unit step of group joint k: by part `part`'s points, and by the two parts
  // of self_part_pairs()[pair] relative to each other.
  double part_motion(std::size_t part, int k) const;
  double pair_motion(std::size_t pair, int k) const;

 private:
  ArmKinematics kinematics_;
  std::vector<std::pair<int, int>> self_pairs_;
  std::vector<std::pair<int, int>> self_part_pairs_;
  std::vector<double> motion_radii_;
  double reach_ = 0.0;
  double min_diameter_ = 0.0;
  std::shared_ptr<const detail::ArmGeometry> geometry_;
  std::shared_ptr<const detail::ArmMotionCoefficients> coefficients_;
};

// Bounds a solid's points' distance from its parent frame's origin (exact for boxes and meshes).
double solid_reach(const Solid& s);

// The FCL geometry of every link's collision solids, with each mesh's convex hull: built once per
// robot model (the hulls cost a tenth of a second for a Panda). Throws ParameterError when no link
// has collision geometry.
std::shared_ptr<const detail::ArmGeometry> make_arm_geometry(const ArmModel& model);

class ArmEnvironment final : public Environment {
 public:
  // `object_ids[i]` names the collision object of scene solid i; `allowed` may pair such ids with
  // link names (the scene's allowed_collision_matrix).
  ArmEnvironment(std::shared_ptr<const SpatialWorld> scene, std::vector<std::string> object_ids,
                 std::shared_ptr<const ArmRobot> robot, const AllowedCollisions& allowed);

  int workspace_dimension() const override { return 3; }
  // A robot of spheres (with_sphere_collision) in a scene of primitives gets the sphere checker
  // (exact sphere distances, docs/arms.md "Sphere model"); anything else FCL's.
  std::unique_ptr<ValidityChecker> make_checker(core::Counters& counters) const override;
  // FCL on the same geometry, whatever it is: the reference the sphere checker is tested against.
  std::unique_ptr<ValidityChecker> make_fcl_checker(core::Counters& counters) const;
  // Whether make_checker gives the sphere checker.
  bool sphere_checked() const { return sphere_checked_; }
  // The sphere checker on a chosen build of its SIMD kernels (kAuto: the CPU's best, as
  // make_checker); both builds give the same answers, which tests compare. Throws ParameterError
  // when !sphere_checked().
  enum class SphereIsa { kAuto, kBaseline, kAvx2 };
  std::unique_ptr<ValidityChecker> make_sphere_checker(core::Counters& counters, SphereIsa isa) const;
  // The build kAuto runs on this CPU: "avx2", or "baseline" where the CPU lacks AVX2.
  static const char* sphere_kernels_in_use();
  Eigen::AlignedBox3d workspace_bounds() const override { return scene_->bounds(); }
  Outline obstacle_outline() const override;
  Shapes2d robot_outline(const State& s) const override;
  bool has_front_view() const override { return true; }
  Outline obstacle_front_outline() const override;
  Shapes2d robot_front_outline(const State& s) const override;
  // The scene's solids one mesh each; every model link (not only the group's) by its URDF name.
  SceneModel scene_model() const override;
  void robot_link_poses(const State& s, std::vector<Eigen::Isometry3d>& out) const override;
  Eigen::Vector3d reference_point(const State& s) const override { return robot_->kinematics().tip_position(s); }
  double robot_min_diameter() const override { return robot_->min_diameter(); }
  double robot_radius() const override { return robot_->reach(); }

  const SpatialWorld& scene() const { return *scene_; }
  const std::vector<std::string>& object_ids() const { return object_ids_; }
  const ArmRobot& robot() const { return *robot_; }
  // Whether the scene allows object solid `object` to touch link `link`.
  bool allowed(std::size_t object, int link) const;
  // What a configuration collides with, in words: "links 'a' and 'b'" or "link 'a' and object
  // 'id'"; empty when it is free.
  std::string first_contact(const State& s) const;

 private:
  std::shared_ptr<const SpatialWorld> scene_;
  std::vector<std::string> object_ids_;
  std::shared_ptr<const ArmRobot> robot_;
  std::vector<std::vector<bool>> allowed_;  // [object][link]
  bool sphere_checked_ = false;
  // The views: solids placed by `view` (identity: top; the front view's frame), projected.
  Outline obstacles_seen_from(const Eigen::Isometry3d& view) const;
  Shapes2d robot_seen_from(const Eigen::Isometry3d& view, const State& s) const;
  mutable std::mutex make_mutex_;  // FCL objects write into shared geometry when made
};

}  // namespace amp::world
