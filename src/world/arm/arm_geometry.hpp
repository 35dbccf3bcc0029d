#pragma once
// Private: the FCL geometry of an ArmRobot's links.
#include <vector>

#include "world/spatial/fcl_scene.hpp"

namespace amp::world::detail {

// One collision solid of one link: its FCL geometry (shared by every checker's object) and pose in
// the link frame.
struct ArmPart {
  int link = 0;
  FclGeometry geometry;
  // A convex shape containing the solid (the mesh's convex hull; a primitive itself): tests against
  // it first, and the exact geometry only when it touches (arm_checker.cpp).
  FclGeometry hull;
  Eigen::Isometry3d local = Eigen::Isometry3d::Identity();
  // A sphere containing the solid, in the link frame: a cheap lower bound on distances.
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double radius = 0.0;
};

struct ArmGeometry {
  std::vector<ArmPart> parts;
};

}  // namespace amp::world::detail
