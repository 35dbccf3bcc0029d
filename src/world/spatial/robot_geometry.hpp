#pragma once
// Private: the FCL geometry of a SpatialRobot's parts.
#include <vector>

#include "world/spatial/fcl_scene.hpp"

namespace amp::world::detail {

// One solid of one link: its FCL geometry (shared by every checker's object) and placement.
struct RobotPart {
  int link = 0;
  FclGeometry geometry;
  Eigen::Isometry3d local = Eigen::Isometry3d::Identity();  // solid pose in the link frame
};

struct RobotGeometry {
  std::vector<RobotPart> parts;
};

}  // namespace amp::world::detail
