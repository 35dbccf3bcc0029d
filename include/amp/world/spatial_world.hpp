#pragma once
#include <memory>
#include <vector>

#include <Eigen/Geometry>

#include "amp/world/mesh_loader.hpp"

namespace amp::world {

namespace detail {
struct FclScene;  // FCL objects and broad phase; FCL stays out of public headers
}

// One solid of a 3-D world or robot: a primitive or a triangle mesh, placed by `pose` in its
// parent frame (the world, or a robot link). Boxes are centred on the pose; cylinders too, with
// their axis along the local z; meshes are in their own coordinates, already scaled. To FCL a
// mesh is its surface: a robot wholly inside a closed mesh does not collide with it (as in OMPL.app).
struct Solid {
  enum class Kind { kBox, kSphere, kCylinder, kMesh };
  Kind kind = Kind::kBox;
  Eigen::Vector3d size = Eigen::Vector3d::Ones();  // box side lengths
  double radius = 0.0;                              // sphere, cylinder
  double length = 0.0;                              // cylinder
  std::shared_ptr<const TriangleMesh> mesh;         // mesh
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();

  // Throw ParameterError for non-positive sizes or an empty mesh.
  static Solid box(const Eigen::Vector3d& size, const Eigen::Isometry3d& pose = Eigen::Isometry3d::Identity());
  static Solid sphere(double radius, const Eigen::Vector3d& center);
  static Solid cylinder(double radius, double length, const Eigen::Isometry3d& pose = Eigen::Isometry3d::Identity());
  // Copies the mesh with each vertex multiplied component-wise by `scale`.
  static Solid mesh_of(const TriangleMesh& mesh, const Eigen::Isometry3d& pose = Eigen::Isometry3d::Identity(),
                       const Eigen::Vector3d& scale = Eigen::Vector3d::Ones());

  // Points whose convex hull is the solid (exact for boxes and meshes, a 16-gon prism for
  // cylinders, the 6 axis extremes for spheres: use radius for those), in the parent frame.
  std::vector<Eigen::Vector3d> hull_points(const Eigen::Isometry3d& parent = Eigen::Isometry3d::Identity()) const;
  // Axis-aligned bounds in the parent frame.
  Eigen::AlignedBox3d bounds(const Eigen::Isometry3d& parent = Eigen::Isometry3d::Identity()) const;
};

// A static 3-D world: solids as FCL collision objects (primitives as FCL shapes, meshes as
// OBB-RSS BVHs), all built once here, with a dynamic AABB tree broad phase over them.
// Immutable after construction, so every thread's checker queries it concurrently.
class SpatialWorld {
 public:
  // Throws ParameterError if the bounds are empty.
  SpatialWorld(std::vector<Solid> obstacles, const Eigen::AlignedBox3d& bounds);
  ~SpatialWorld();
  SpatialWorld(const SpatialWorld&) = delete;
  SpatialWorld& operator=(const SpatialWorld&) = delete;

  const std::vector<Solid>& obstacles() const { return obstacles_; }
  const Eigen::AlignedBox3d& bounds() const { return bounds_; }
  const detail::FclScene& scene() const { return *scene_; }

 private:
  std::vector<Solid> obstacles_;
  Eigen::AlignedBox3d bounds_;
  std::unique_ptr<detail::FclScene> scene_;
};

}  // namespace amp::world
