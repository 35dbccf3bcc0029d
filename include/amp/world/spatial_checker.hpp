#pragma once
#include <memory>

#include "amp/world/spatial_robot.hpp"
#include "amp/world/spatial_world.hpp"
#include "amp/world/validity_checker.hpp"

namespace amp::world {

// How a 3-D robot must stay inside the workspace bounds.
enum class SpatialBoundsCheck {
  kRobotAabb,       // every part's world-frame box (exact for boxes, spheres, cylinders; the rotated
                    // local box for meshes, hence conservative) lies inside: our YAML problems
  kReferencePoint,  // only the reference point (body origin) must lie inside: OMPL.app's rule,
                    // used for its .cfg problems, whose robots may poke out of the volume
};

// A robot's validity checker in an FCL world. It owns one FCL collision object per robot part
// (sharing the geometry built once by SpatialRobot), sets their transforms per check and queries
// the world's broad phase with early exit; request/result objects are reused, so a check never
// allocates. One per thread.
class SpatialChecker final : public ValidityChecker {
 public:
  SpatialChecker(std::shared_ptr<const SpatialWorld> world, SpatialRobot robot, SpatialBoundsCheck bounds_check,
                 core::Counters& counters);
  ~SpatialChecker() override;

 private:
  struct Scratch;  // FCL objects and reused query buffers

  bool check(const State& s) const override;
  Clearance compute_clearance(const State& s) const override;
  // min(FCL distance to the world, distance to leave the bounds, half the distance between
  // non-adjacent links); spatial_certification.cpp.
  double compute_free_radius(const State& s) const override;
  // Rigid: |dp| + R * (rotation angle), R bounding every point's (and every part box corner's)
  // distance from the body origin. SCARA: per joint, its change times the reach it turns.
  double compute_motion_bound(const State& a, const State& b) const override;
  double bounds_margin(const State& s) const;
  // Places the robot's objects at state s.
  void place(const State& s) const;
  bool inside_bounds(const State& s) const;
  // World-frame box of part i as placed (exact for boxes, spheres and cylinders; a mesh's rotated
  // local box).
  Eigen::AlignedBox3d part_box(std::size_t i) const;

  std::shared_ptr<const SpatialWorld> world_;
  SpatialRobot robot_;
  SpatialBoundsCheck bounds_check_;
  std::unique_ptr<Scratch> scratch_;
  double motion_radius_ = 0.0;  // rigid and sphere robots: see compute_motion_bound
};

}  // namespace amp::world
