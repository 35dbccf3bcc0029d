#include <array>
#include <cmath>
#include <limits>

#include "amp/world/spatial_environment.hpp"
#include "world/spatial/robot_geometry.hpp"

namespace amp::world {

namespace {

// Enough for every robot we build (a rigid body of many shapes spills into a heap vector made
// once at construction; the fixed array only serves the link poses).
using LinkPoses = std::array<Eigen::Isometry3d, SpatialRobot::kMaxLinks>;

// What a part needs for the exact world-frame bounds test.
struct PartBounds {
  Solid::Kind kind;
  Eigen::Vector3d center;  // of the local box, in the part frame
  Eigen::Vector3d half;    // local half extents (box, mesh)
  double radius = 0.0;
  double half_length = 0.0;
};

struct CollideData {
  fcl::CollisionRequestd request;
  fcl::CollisionResultd result;
  bool hit = false;
};

bool collide_callback(fcl::CollisionObjectd* a, fcl::CollisionObjectd* b, void* raw) {
  auto* data = static_cast<CollideData*>(raw);
  data->result.clear();
  fcl::collide(a, b, data->request, data->result);
  data->hit = data->result.isCollision();
  return data->hit;  // true stops the broad phase: one contact decides
}

struct DistanceData {
  fcl::DistanceRequestd request{true};  // nearest points wanted
  fcl::DistanceResultd pair;            // reused for every pair
  const fcl::CollisionObjectd* robot = nullptr;
  double distance = std::numeric_limits<double>::infinity();
  Eigen::Vector3d robot_point, obstacle_point;
};

bool is_mesh(const fcl::CollisionObjectd* o) { return o->getObjectType() == fcl::OT_BVH; }

bool distance_callback(fcl::CollisionObjectd* a, fcl::CollisionObjectd* b, void* raw, double& dist) {
  auto* data = static_cast<DistanceData*>(raw);
  const fcl::CollisionObjectd* robot = a == data->robot ? a : b;  // the broad phase promises no order
  const fcl::CollisionObjectd* obstacle = a == data->robot ? b : a;
  // FCL 0.7 returns the nearest points of a shape-mesh pair swapped, and those of a
  // mesh-sphere pair in the objects' local frames: query with the mesh first and fix the frames.
  const bool swap = !is_mesh(robot) && is_mesh(obstacle);
  const fcl::CollisionObjectd* first = swap ? obstacle : robot;
  const fcl::CollisionObjectd* second = swap ? robot : obstacle;
  data->pair.clear();
  fcl::distance(first, second, data->request, data->pair);
  if (data->pair.min_distance < data->distance) {
    Eigen::Vector3d p0 = data->pair.nearest_points[0], p1 = data->pair.nearest_points[1];
    if (is_mesh(first) && second->getNodeType() == fcl::GEOM_SPHERE) {
      p0 = first->getTransform() * p0;
      p1 = second->getTransform() * p1;
    }
    data->distance = data->pair.min_distance;
    data->robot_point = swap ? p1 : p0;
    data->obstacle_point = swap ? p0 : p1;
  }
  dist = data->distance;
  return dist <= 0.0;
}

}  // namespace

struct SpatialChecker::Scratch {
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> objects;  // one per robot part
  std::vector<PartBounds> bounds;
  std::vector<std::pair<int, int>> self_pairs;  // part indices
  LinkPoses poses;
  CollideData collide;
  DistanceData distance;
};

SpatialChecker::SpatialChecker(std::shared_ptr<const SpatialWorld> world, SpatialRobot robot,
                               SpatialBoundsCheck bounds_check, core::Counters& counters)
    : ValidityChecker(counters),
      world_(std::move(world)),
      robot_(std::move(robot)),
      bounds_check_(bounds_check),
      scratch_(std::make_unique<Scratch>()) {
  const auto& parts = robot_.geometry().parts;
  std::vector<const Solid*> solids;
  for (int l = 0; l < robot_.link_count(); ++l) {
    for (const Solid& s : robot_.link_solids(l)) solids.push_back(&s);
  }
  for (std::size_t i = 0; i < parts.size(); ++i) {
    scratch_->objects.push_back(std::make_unique<fcl::CollisionObjectd>(parts[i].geometry));
    const Solid& s = *solids[i];
    PartBounds b{s.kind, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), s.radius, 0.5 * s.length};
    if (s.kind == Solid::Kind::kBox) b.half = 0.5 * s.size;
    if (s.kind == Solid::Kind::kMesh) {
      const Eigen::AlignedBox3d box = mesh_bounds(*s.mesh);
      b.center = box.center();
      b.half = 0.5 * box.sizes();
    }
    scratch_->bounds.push_back(b);
  }
  for (const auto& [la, lb] : robot_.self_pairs()) {
    for (std::size_t i = 0; i < parts.size(); ++i) {
      for (std::size_t j = 0; j < parts.size(); ++j) {
        if (parts[i].link == la && parts[j].link == lb) scratch_->self_pairs.emplace_back(i, j);
      }
    }
  }
}

SpatialChecker::~SpatialChecker() = default;

void SpatialChecker::place(const State& s) const {
  Scratch& w = *scratch_;
  robot_.link_poses(s, w.poses.data());
  const auto& parts = robot_.geometry().parts;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const Eigen::Isometry3d pose = w.poses[static_cast<std::size_t>(parts[i].link)] * parts[i].local;
    w.objects[i]->setTransform(detail::to_fcl(pose));
    w.objects[i]->computeAABB();  // the broad phase prunes with it
  }
}

bool SpatialChecker::inside_bounds(const State& s) const {
  const Eigen::AlignedBox3d& box = world_->bounds();
  if (bounds_check_ == SpatialBoundsCheck::kReferencePoint) {
    if (robot_.kind() == SpatialRobot::Kind::kScara) {
      return box.contains(scratch_->poses[SpatialRobot::kMaxLinks - 1] * robot_.scara_params().tip);
    }
    return box.contains(s.head<3>());
  }
  const Scratch& w = *scratch_;
  for (std::size_t i = 0; i < w.objects.size(); ++i) {
    const fcl::Transform3d& t = w.objects[i]->getTransform();
    const PartBounds& b = w.bounds[i];
    const Eigen::Vector3d c = t * b.center;
    Eigen::Vector3d half;
    switch (b.kind) {
      case Solid::Kind::kSphere:
        half.setConstant(b.radius);
        break;
      case Solid::Kind::kCylinder:
        for (int k = 0; k < 3; ++k) {
          const double a = t.linear()(k, 2);
          half[k] = b.half_length * std::abs(a) + b.radius * std::sqrt(std::max(0.0, 1.0 - a * a));
        }
        break;
      default:
        half = t.linear().cwiseAbs() * b.half;
    }
    if (((c - half).array() < box.min().array()).any() || ((c + half).array() > box.max().array()).any()) return false;
  }
  return true;
}

bool SpatialChecker::check(const State& s) const {
  Scratch& w = *scratch_;
  place(s);
  if (!inside_bounds(s)) return false;
  for (const auto& [i, j] : w.self_pairs) {
    w.collide.result.clear();
    if (fcl::collide(w.objects[i].get(), w.objects[j].get(), w.collide.request, w.collide.result) > 0) return false;
  }
  const auto& manager = world_->scene().manager;
  for (const auto& obj : w.objects) {
    w.collide.hit = false;
    manager.collide(obj.get(), &w.collide, collide_callback);
    if (w.collide.hit) return false;
  }
  return true;
}

Clearance SpatialChecker::compute_clearance(const State& s) const {
  Scratch& w = *scratch_;
  place(s);
  Clearance best;
  best.distance = std::numeric_limits<double>::infinity();
  const auto& manager = world_->scene().manager;
  DistanceData& d = w.distance;
  d.distance = std::numeric_limits<double>::infinity();
  for (const auto& obj : w.objects) {
    d.robot = obj.get();
    manager.distance(obj.get(), &d, distance_callback);
    if (d.distance <= 0.0) break;
  }
  best.distance = std::max(0.0, d.distance);
  best.robot_point = d.robot_point;
  best.obstacle_point = d.obstacle_point;
  return best;
}

}  // namespace amp::world
