#pragma once
#include <vector>

#include <Eigen/Core>

#include "amp/core/state.hpp"
#include "amp/world/shapes2d.hpp"

namespace amp::world {

// One link of an arm or linkage: a rectangle from its joint along +x of the link frame, `length`
// long, `width` wide, extended by width/2 beyond both joints so that consecutive links overlap
// around their shared joint like a capsule would.
struct LinkSpec {
  double length = 1.0;
  double width = 0.1;
};

// A planar robot: links, each a set of shapes in its own frame, plus the kinematics that place the
// links from a state. Immutable; cheap to copy (a few small vectors).
class PlanarRobot {
 public:
  enum class Kind {
    kRigid,        // state (x, y, theta), one link
    kTranslating,  // state (x, y), one link (disc or point robot)
    kFixedArm,     // state = joint angles; base pose fixed
    kFreeLinkage,  // state (x, y, theta) of link 0, then the joint angles
  };

  // Throws ParameterError for invalid shapes (see validate_shapes) or an empty body.
  static PlanarRobot rigid(Shapes2d body);
  // A translating body; a circle of radius 0 is a point robot.
  static PlanarRobot translating(Shapes2d body);
  // Joint i sits at the end of link i-1 (joint 0 at the base). Throws ParameterError for no links,
  // a non-positive length or width, or a middle link shorter than its width (its neighbours
  // would always collide).
  static PlanarRobot fixed_arm(Pose2 base, std::vector<LinkSpec> links);
  static PlanarRobot free_linkage(std::vector<LinkSpec> links);

  Kind kind() const { return kind_; }
  int link_count() const { return static_cast<int>(links_.size()); }
  int state_dimension() const;
  // Shapes of each link in its own frame.
  const std::vector<Shapes2d>& links() const { return links_; }
  // Arms and linkages only (empty otherwise).
  const std::vector<LinkSpec>& link_specs() const { return specs_; }
  const Pose2& base() const { return base_; }

  // Pose of every link in the world frame; `out` holds link_count() poses. No allocation.
  void link_poses(const State& s, Pose2* out) const;
  // Links i and j with |i - j| >= 2 must not overlap (arms and linkages).
  bool has_self_collision() const { return kind_ == Kind::kFixedArm || kind_ == Kind::kFreeLinkage; }

  // Smallest width of the robot: hull width of a rigid body, 2r for a disc, the narrowest link
  // width for arms and linkages.
  double min_diameter() const { return min_diameter_; }
  // Largest distance of a robot point from the origin of link 0 (base for arms), over all states.
  double radius() const { return radius_; }

  // Link-0 origin for rigid and translating robots; the end of the last link for arms/linkages.
  Eigen::Vector2d reference_point(const State& s) const;
  // All shapes placed in the world frame (allocates: for drawing, not for checking).
  Shapes2d outline(const State& s) const;

 private:
  PlanarRobot() = default;
  static PlanarRobot chain(Kind kind, Pose2 base, std::vector<LinkSpec> links);

  Kind kind_ = Kind::kRigid;
  std::vector<Shapes2d> links_;
  std::vector<LinkSpec> specs_;
  Pose2 base_;
  double min_diameter_ = 0.0;
  double radius_ = 0.0;
};

// Shapes placed by a pose (allocates).
Shapes2d transform_shapes(const Shapes2d& shapes, const Pose2& pose);

}  // namespace amp::world
