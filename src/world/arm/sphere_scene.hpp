#pragma once
// Private: a MoveIt scene's primitives laid out for sphere queries (sphere_checker.cpp). Distances
// are exact signed distances from a point to a box, a z-axis cylinder or a sphere, so a sphere of
// radius r at p is clear of an obstacle by exactly distance(p) - r.
#include <cstddef>
#include <vector>

#include <Eigen/Geometry>

#include "amp/world/spatial_world.hpp"

namespace amp::world::detail {

// Structure of arrays: one entry per obstacle, grouped by kind (boxes, then cylinders, then
// spheres), so that a kind's loop reads contiguous lanes (the vectorised kernel, sphere_kernels.hpp).
struct SphereScene {
  // Per obstacle, in the order above: the world-to-obstacle rotation's rows and the centre (for a
  // sphere obstacle the rotation is the identity), its half extents (box: hx hy hz; cylinder:
  // radius, half length, 0; sphere: radius, 0, 0), and which scene solid it is.
  std::vector<double> r[9];
  std::vector<double> cx, cy, cz;
  std::vector<double> ex, ey, ez;
  std::vector<double> bound;  // radius of a ball about the centre holding the whole obstacle
  std::vector<std::size_t> object;
  std::size_t boxes = 0, cylinders = 0, spheres = 0;

  std::size_t size() const { return object.size(); }
};

// Whether every solid of the scene is a primitive the sphere checker measures (no meshes).
bool sphere_scene_supported(const std::vector<Solid>& solids);
// Throws ParameterError on a mesh solid (check sphere_scene_supported first).
SphereScene make_sphere_scene(const std::vector<Solid>& solids);

// Whether p is farther than `gap` from obstacle i by its bounding ball alone (no rotation): the
// cheap test before obstacle_distance.
inline bool obstacle_beyond(const SphereScene& scene, std::size_t i, const Eigen::Vector3d& p, double gap) {
  const double dx = p.x() - scene.cx[i], dy = p.y() - scene.cy[i], dz = p.z() - scene.cz[i];
  const double reach = gap + scene.bound[i];
  return reach >= 0.0 && dx * dx + dy * dy + dz * dz > reach * reach;
}
// Signed distance from p to obstacle i (negative inside). Scalar, the reference of the kernels.
double obstacle_distance(const SphereScene& scene, std::size_t i, const Eigen::Vector3d& p);

}  // namespace amp::world::detail
