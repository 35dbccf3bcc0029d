#include "amp/world/spatial_world.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "amp/core/error.hpp"
#include "world/spatial/fcl_scene.hpp"

namespace amp::world {

namespace {
// Sides of the polygon standing in for a cylinder's circular ends in hulls and outlines.
constexpr int kCylinderSides = 16;
}  // namespace

Solid Solid::box(const Eigen::Vector3d& size, const Eigen::Isometry3d& pose) {
  if (!(size.minCoeff() > 0.0)) throw ParameterError("box: sizes must be positive");
  Solid s;
  s.kind = Kind::kBox;
  s.size = size;
  s.pose = pose;
  return s;
}

Solid Solid::sphere(double radius, const Eigen::Vector3d& center) {
  if (!(radius > 0.0)) throw ParameterError("sphere: radius must be positive, got " + std::to_string(radius));
  Solid s;
  s.kind = Kind::kSphere;
  s.radius = radius;
  s.pose = Eigen::Isometry3d(Eigen::Translation3d(center));
  return s;
}

Solid Solid::cylinder(double radius, double length, const Eigen::Isometry3d& pose) {
  if (!(radius > 0.0) || !(length > 0.0)) throw ParameterError("cylinder: radius and length must be positive");
  Solid s;
  s.kind = Kind::kCylinder;
  s.radius = radius;
  s.length = length;
  s.pose = pose;
  return s;
}

Solid Solid::mesh_of(const TriangleMesh& mesh, const Eigen::Isometry3d& pose, const Eigen::Vector3d& scale) {
  if (mesh.triangles.empty()) throw ParameterError("mesh: no triangles");
  if (!(scale.minCoeff() > 0.0)) throw ParameterError("mesh: scale must be positive");
  auto scaled = std::make_shared<TriangleMesh>(mesh);
  for (Eigen::Vector3d& v : scaled->vertices) v = v.cwiseProduct(scale);
  Solid s;
  s.kind = Kind::kMesh;
  s.mesh = std::move(scaled);
  s.pose = pose;
  return s;
}

std::vector<Eigen::Vector3d> Solid::hull_points(const Eigen::Isometry3d& parent) const {
  const Eigen::Isometry3d to_parent = parent * pose;
  std::vector<Eigen::Vector3d> pts;
  switch (kind) {
    case Kind::kBox:
      for (int i = 0; i < 8; ++i) {
        const Eigen::Vector3d corner(i & 1 ? 0.5 : -0.5, i & 2 ? 0.5 : -0.5, i & 4 ? 0.5 : -0.5);
        pts.push_back(to_parent * corner.cwiseProduct(size));
      }
      break;
    case Kind::kSphere:
      for (int axis = 0; axis < 3; ++axis) {
        for (double sign : {-1.0, 1.0}) pts.push_back(to_parent * (sign * radius * Eigen::Vector3d::Unit(axis)));
      }
      break;
    case Kind::kCylinder:
      for (int i = 0; i < kCylinderSides; ++i) {
        const double a = 2.0 * std::numbers::pi * i / kCylinderSides;
        // Circumscribed polygon, so that the hull contains the cylinder.
        const double r = radius / std::cos(std::numbers::pi / kCylinderSides);
        for (double z : {-0.5 * length, 0.5 * length}) pts.push_back(to_parent * Eigen::Vector3d(r * std::cos(a), r * std::sin(a), z));
      }
      break;
    case Kind::kMesh:
      for (const Eigen::Vector3d& v : mesh->vertices) pts.push_back(to_parent * v);
      break;
  }
  return pts;
}

Eigen::AlignedBox3d Solid::bounds(const Eigen::Isometry3d& parent) const {
  Eigen::AlignedBox3d box;
  if (kind == Kind::kSphere) {
    const Eigen::Vector3d c = parent * pose.translation();
    return Eigen::AlignedBox3d(c.array() - radius, c.array() + radius);
  }
  if (kind == Kind::kCylinder) {  // exact: end discs' extents along each world axis
    const Eigen::Isometry3d to_parent = parent * pose;
    const Eigen::Vector3d axis = to_parent.linear().col(2);
    const Eigen::Vector3d c = to_parent.translation();
    Eigen::Vector3d half;
    for (int i = 0; i < 3; ++i) half[i] = 0.5 * length * std::abs(axis[i]) + radius * std::sqrt(std::max(0.0, 1.0 - axis[i] * axis[i]));
    return Eigen::AlignedBox3d(c - half, c + half);
  }
  for (const Eigen::Vector3d& p : hull_points(parent)) box.extend(p);
  return box;
}

namespace detail {

FclGeometry make_fcl_geometry(const Solid& solid) {
  switch (solid.kind) {
    case Solid::Kind::kBox:
      return std::make_shared<fcl::Boxd>(solid.size);
    case Solid::Kind::kSphere:
      return std::make_shared<fcl::Sphered>(solid.radius);
    case Solid::Kind::kCylinder:
      return std::make_shared<fcl::Cylinderd>(solid.radius, solid.length);
    case Solid::Kind::kMesh: {
      auto model = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
      std::vector<fcl::Triangle> tris;
      tris.reserve(solid.mesh->triangles.size());
      for (const Eigen::Vector3i& t : solid.mesh->triangles) tris.emplace_back(t[0], t[1], t[2]);
      model->beginModel();
      model->addSubModel(solid.mesh->vertices, tris);
      model->endModel();
      model->computeLocalAABB();
      return model;
    }
  }
  return nullptr;
}

}  // namespace detail

SpatialWorld::SpatialWorld(std::vector<Solid> obstacles, const Eigen::AlignedBox3d& bounds)
    : obstacles_(std::move(obstacles)), bounds_(bounds), scene_(std::make_unique<detail::FclScene>()) {
  if (bounds_.isEmpty() || !(bounds_.sizes().minCoeff() > 0.0)) {
    throw ParameterError("spatial world: bounds must have min < max on every axis");
  }
  std::vector<fcl::CollisionObjectd*> raw;
  for (const Solid& s : obstacles_) {
    auto obj = std::make_unique<fcl::CollisionObjectd>(detail::make_fcl_geometry(s), detail::to_fcl(s.pose));
    obj->computeAABB();
    raw.push_back(obj.get());
    scene_->objects.push_back(std::move(obj));
  }
  if (!raw.empty()) scene_->manager.registerObjects(raw);
  scene_->manager.setup();
}

SpatialWorld::~SpatialWorld() = default;

}  // namespace amp::world
