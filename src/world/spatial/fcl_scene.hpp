#pragma once
// Private to the spatial world: the FCL side of SpatialWorld and SpatialRobot.
#include <memory>
#include <vector>

#include <fcl/fcl.h>

#include "amp/world/spatial_world.hpp"

namespace amp::world::detail {

using FclGeometry = std::shared_ptr<fcl::CollisionGeometryd>;

// The FCL geometry of a solid in its own frame (without solid.pose): an FCL primitive, or an
// OBB-RSS BVH for meshes. Built once; shared by every object that uses it.
FclGeometry make_fcl_geometry(const Solid& solid);

inline fcl::Transform3d to_fcl(const Eigen::Isometry3d& pose) {
  fcl::Transform3d t;
  t.matrix() = pose.matrix();
  return t;
}

struct FclScene {
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> objects;
  // Broad phase over `objects`; its queries are const and thread-safe once set up.
  fcl::DynamicAABBTreeCollisionManagerd manager;
};

}  // namespace amp::world::detail
