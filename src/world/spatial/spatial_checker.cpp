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
    // Every point the bounds test or FCL looks at: hull points, and the local box of a mesh.
    for (const Eigen::Vector3d& p : s.hull_points()) motion_radius_ = std::max(motion_radius_, p.norm());
    if (s.kind == Solid::Kind::kSphere) motion_radius_ = std::max(motion_radius_, s.pose.translation().norm() + s.radius);
    if (s.kind == Solid::Kind::kMesh) {
      const Eigen::AlignedBox3d box = mesh_bounds(*s.mesh);
      for (int c = 0; c < 8; ++c) {
        motion_radius_ = std::max(motion_radius_, (s.pose * box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c))).norm());
      }
    }
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
  for (std::size_t i = 0; i < scratch_->objects.size(); ++i) {
    const Eigen::AlignedBox3d b = part_box(i);
    if ((b.min().array() < box.min().array()).any() || (b.max().array() > box.max().array()).any()) return false;
  }
  return true;
}

Eigen::AlignedBox3d SpatialChecker::part_box(std::size_t i) const {
  const Scratch& w = *scratch_;
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
  return {c - half, c + half};
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

double SpatialChecker::bounds_margin(const State& s) const {
  const Eigen::AlignedBox3d& box = world_->bounds();
  const auto margin = [&box](const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
    return std::max(0.0, std::min((lo - box.min()).minCoeff(), (box.max() - hi).minCoeff()));
  };
  const Scratch& w = *scratch_;
  if (bounds_check_ == SpatialBoundsCheck::kReferencePoint) {
    const Eigen::Vector3d p = robot_.kind() == SpatialRobot::Kind::kScara
                                  ? Eigen::Vector3d(w.poses[SpatialRobot::kMaxLinks - 1] * robot_.scara_params().tip)
                                  : Eigen::Vector3d(s.head<3>());
    return margin(p, p);
  }
  // The boxes inside_bounds() tests, whose corners the motion bound covers.
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < w.objects.size(); ++i) {
    const Eigen::AlignedBox3d b = part_box(i);
    best = std::min(best, margin(b.min(), b.max()));
  }
  return best;
}

double SpatialChecker::compute_free_radius(const State& s) const {
  if (!check(s)) return 0.0;
  double r = std::min(compute_clearance(s).distance, bounds_margin(s));
  Scratch& w = *scratch_;
  for (const auto& [i, j] : w.self_pairs) {
    // Two links may approach each other at twice the speed of either.
    fcl::DistanceRequestd request;
    fcl::DistanceResultd result;
    fcl::distance(w.objects[i].get(), w.objects[j].get(), request, result);
    r = std::min(r, 0.5 * std::max(0.0, result.min_distance));
  }
  return r;
}

double SpatialChecker::compute_motion_bound(const State& a, const State& b) const {
  switch (robot_.kind()) {
    case SpatialRobot::Kind::kSphere:
      return (b.head<3>() - a.head<3>()).norm() ;
    case SpatialRobot::Kind::kRigid: {
      // Se3Space slerps the short arc: a point at distance rho from the origin travels rho * angle.
      const Eigen::Quaterniond qa(a[6], a[3], a[4], a[5]), qb(b[6], b[3], b[4], b[5]);
      const double angle = qa.normalized().angularDistance(qb.normalized());
      return (b.head<3>() - a.head<3>()).norm() + motion_radius_ * angle;
    }
    case SpatialRobot::Kind::kScara: {
      // (base yaw, slide, shoulder, elbow, wrist yaw), all revolute but the slide: each yaw turns
      // the links beyond it about a vertical axis, the slide lifts them. Reaches are horizontal
      // distances from each axis, with a link radius of slack for the boxes' corners.
      const ScaraParams& p = robot_.scara_params();
      double tool = 2.0 * p.link_radius;
      for (const Solid& t : p.tool) {
        for (const Eigen::Vector3d& h : t.hull_points()) tool = std::max(tool, h.head<2>().norm());
      }
      const double elbow = p.forearm + tool + p.link_radius;
      const double shoulder = p.upper_arm + elbow + p.link_radius;
      const double base = shoulder + p.link_radius;
      return base * std::abs(b[0] - a[0]) + std::abs(b[1] - a[1]) + shoulder * std::abs(b[2] - a[2]) +
             elbow * std::abs(b[3] - a[3]) + tool * std::abs(b[4] - a[4]);
    }
  }
  return std::numeric_limits<double>::infinity();
}

}  // namespace amp::world
