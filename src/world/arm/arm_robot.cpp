#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "amp/core/error.hpp"
#include "amp/world/arm_environment.hpp"
#include "amp/world/convex_hull.hpp"
#include "world/arm/arm_geometry.hpp"

namespace amp::world {

namespace {

// A bound on the distance of every point of link `l`'s subtree from l's frame origin, over all
// configurations: rotations below keep distances from their own origins, so the bound adds up.
double subtree_reach(const ArmModel& m, int l) {
  double r = 0.0;
  for (const Solid& s : m.link(l).collision) r = std::max(r, solid_reach(s));
  for (const int j : m.link(l).child_joints) {
    const ArmJoint& joint = m.joint(j);
    r = std::max(r, joint.origin.translation().norm() + detail::joint_travel(joint) + subtree_reach(m, joint.child_link));
  }
  return r;
}

double joint_radius(const ArmModel& m, int j) {
  const ArmJoint& joint = m.joint(j);
  return joint.type == ArmJointType::kPrismatic ? 1.0 : subtree_reach(m, joint.child_link);
}

// The smallest side of a solid's bounds in its own frame.
double solid_min_side(const Solid& s) {
  switch (s.kind) {
    case Solid::Kind::kSphere: return 2.0 * s.radius;
    case Solid::Kind::kCylinder: return std::min(2.0 * s.radius, s.length);
    case Solid::Kind::kBox: return s.size.minCoeff();
    case Solid::Kind::kMesh: return mesh_bounds(*s.mesh).sizes().minCoeff();
  }
  return 0.0;
}

// The part with its bounding sphere: centred on its bounds, radius to its farthest point.
// FCL's convex shape of a mesh's hull (faces as vertex counts followed by indices).
detail::FclGeometry convex_geometry(const TriangleMesh& mesh) {
  const TriangleMesh hull = convex_hull(mesh);
  auto vertices = std::make_shared<std::vector<Eigen::Vector3d>>(hull.vertices);
  auto faces = std::make_shared<std::vector<int>>();
  for (const Eigen::Vector3i& t : hull.triangles) faces->insert(faces->end(), {3, t[0], t[1], t[2]});
  return std::make_shared<fcl::Convexd>(vertices, static_cast<int>(hull.triangles.size()), faces);
}

detail::ArmPart make_part(int link, const Solid& s) {
  detail::FclGeometry exact = detail::make_fcl_geometry(s);
  detail::FclGeometry hull = exact;
  if (s.kind == Solid::Kind::kMesh) {
    try {
      hull = convex_geometry(*s.mesh);
    } catch (const ParameterError&) {  // a flat mesh: no hull, the exact tests alone
    }
  }
  hull->computeLocalAABB();
  detail::ArmPart part{link, exact, hull, s.pose, Eigen::Vector3d::Zero(), 0.0};
  part.center = s.bounds().center();
  Solid local = s;
  local.pose = Eigen::Isometry3d::Identity();
  local.pose.translation() = s.pose.translation() - part.center;
  local.pose.linear() = s.pose.linear();
  part.radius = solid_reach(local);
  part.reach = solid_reach(s);
  return part;
}

}  // namespace

double solid_reach(const Solid& s) {
  switch (s.kind) {
    case Solid::Kind::kSphere:
      return s.pose.translation().norm() + s.radius;
    case Solid::Kind::kCylinder:
      return s.pose.translation().norm() + std::hypot(s.radius, 0.5 * s.length);
    default: {
      double r = 0.0;
      for (const Eigen::Vector3d& p : s.hull_points()) r = std::max(r, p.norm());
      return r;
    }
  }
}

std::shared_ptr<const detail::ArmGeometry> make_arm_geometry(const ArmModel& m) {
  auto geometry = std::make_shared<detail::ArmGeometry>();
  for (std::size_t l = 0; l < m.links().size(); ++l) {
    for (const Solid& s : m.links()[l].collision) geometry->parts.push_back(make_part(static_cast<int>(l), s));
  }
  if (geometry->parts.empty()) throw ParameterError("arm: no link has collision geometry");
  return geometry;
}

ArmRobot::ArmRobot(ArmKinematics kinematics, std::shared_ptr<const detail::ArmGeometry> geometry,
                   const std::vector<std::pair<std::string, std::string>>& disabled)
    : kinematics_(std::move(kinematics)), geometry_(std::move(geometry)) {
  const ArmModel& m = kinematics_.model();
  std::set<std::pair<int, int>> off;
  for (const auto& [a, b] : disabled) {
    const int la = m.link_index(a), lb = m.link_index(b);
    if (la < 0 || lb < 0) continue;  // an SRDF may name links of another variant of the robot: MoveIt ignores them
    off.emplace(std::min(la, lb), std::max(la, lb));
  }
  const int links = static_cast<int>(m.links().size());
  for (int a = 0; a < links; ++a) {
    for (int b = a + 1; b < links; ++b) {
      if (!m.link(a).collision.empty() && !m.link(b).collision.empty() && off.count({a, b}) == 0) self_pairs_.emplace_back(a, b);
    }
  }
  // Motion radii: each group joint's own subtree, plus its mimic followers' scaled by their multipliers.
  for (const int j : kinematics_.group().joints) {
    double r = joint_radius(m, j);
    for (std::size_t f = 0; f < m.joints().size(); ++f) {
      if (m.joint(static_cast<int>(f)).mimic_joint == j) {
        r += std::abs(m.joint(static_cast<int>(f)).mimic_multiplier) * joint_radius(m, static_cast<int>(f));
      }
    }
    motion_radii_.push_back(r);
  }
  reach_ = subtree_reach(m, 0);
  min_diameter_ = std::numeric_limits<double>::infinity();
  for (const ArmLink& link : m.links()) {
    for (const Solid& s : link.collision) min_diameter_ = std::min(min_diameter_, solid_min_side(s));
  }
  const auto& parts = geometry_->parts;
  for (const auto& [la, lb] : self_pairs_) {
    for (std::size_t i = 0; i < parts.size(); ++i) {
      for (std::size_t k = 0; k < parts.size(); ++k) {
        if (parts[i].link == la && parts[k].link == lb) self_part_pairs_.emplace_back(static_cast<int>(i), static_cast<int>(k));
      }
    }
  }
  coefficients_ = std::make_shared<const detail::ArmMotionCoefficients>(
      detail::arm_motion_coefficients(kinematics_, *geometry_, self_part_pairs_));
}

std::size_t ArmRobot::part_count() const { return geometry_->parts.size(); }
int ArmRobot::part_link(std::size_t part) const { return geometry_->parts.at(part).link; }
double ArmRobot::part_motion(std::size_t part, int k) const {
  return coefficients_->part.at(part * static_cast<std::size_t>(coefficients_->joints) + static_cast<std::size_t>(k));
}
double ArmRobot::pair_motion(std::size_t pair, int k) const {
  return coefficients_->pair.at(pair * static_cast<std::size_t>(coefficients_->joints) + static_cast<std::size_t>(k));
}

}  // namespace amp::world
