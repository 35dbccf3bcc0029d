#include "amp/world/spatial_robot.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "amp/core/error.hpp"
#include "world/spatial/robot_geometry.hpp"

namespace amp::world {

namespace {

enum ScaraLink { kColumn = 0, kUpperArm = 1, kForearm = 2, kWrist = 3, kTool = 4 };

Eigen::Isometry3d translation(const Eigen::Vector3d& p) { return Eigen::Isometry3d(Eigen::Translation3d(p)); }

Eigen::Isometry3d yawed(const Eigen::Vector3d& p, double yaw) {
  Eigen::Isometry3d t = translation(p);
  t.rotate(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()));
  return t;
}

std::vector<std::vector<Solid>> scara_links(const ScaraParams& p) {
  const double r = p.link_radius;
  std::vector<std::vector<Solid>> links(SpatialRobot::kMaxLinks);
  links[kColumn].push_back(Solid::cylinder(r, p.column_height, translation({0, 0, 0.5 * p.column_height})));
  links[kUpperArm].push_back(Solid::box({p.upper_arm, 2 * r, 2 * r}, translation({0.5 * p.upper_arm, 0, 0})));
  links[kForearm].push_back(Solid::box({p.forearm, 2 * r, 2 * r}, translation({0.5 * p.forearm, 0, 0})));
  links[kWrist].push_back(Solid::cylinder(r, p.wrist_length, translation({0, 0, -0.5 * p.wrist_length})));
  links[kTool] = p.tool;
  return links;
}

}  // namespace

void ScaraParams::validate() const {
  auto positive = [](double v, const char* name) {
    if (!(v > 0.0)) throw ParameterError(std::string("scara: ") + name + " must be positive, got " + std::to_string(v));
  };
  positive(column_height, "column_height");
  positive(upper_arm, "upper_arm");
  positive(forearm, "forearm");
  positive(link_radius, "link_radius");
  positive(wrist_length, "wrist_length");
  if (!(slide_lo < slide_hi) || slide_lo < 0.0 || slide_hi > column_height) {
    throw ParameterError("scara: slide must satisfy 0 <= lo < hi <= column_height");
  }
  for (const auto& [lo, hi] : limits) {
    if (!(lo < hi) || hi - lo > 2.0 * std::numbers::pi + 1e-9) {
      throw ParameterError("scara: joint limits need lo < hi and hi - lo <= 2 pi");
    }
  }
  if (tool.empty()) throw ParameterError("scara: the tool needs at least one box");
}

SpatialRobot::SpatialRobot(Kind kind, std::vector<std::vector<Solid>> links) : kind_(kind), links_(std::move(links)) {
  auto geometry = std::make_shared<detail::RobotGeometry>();
  for (int i = 0; i < link_count(); ++i) {
    for (const Solid& s : links_[static_cast<std::size_t>(i)]) {
      geometry->parts.push_back({i, detail::make_fcl_geometry(s), s.pose});
    }
  }
  geometry_ = std::move(geometry);
}

SpatialRobot SpatialRobot::rigid(std::vector<Solid> body) {
  if (body.empty()) throw ParameterError("rigid robot: no shapes");
  SpatialRobot robot(Kind::kRigid, {std::move(body)});
  Eigen::AlignedBox3d box;
  for (const Solid& s : robot.links_[0]) {
    box.extend(s.bounds());
    if (s.kind == Solid::Kind::kSphere) {
      robot.radius_ = std::max(robot.radius_, s.pose.translation().norm() + s.radius);
    } else {
      for (const Eigen::Vector3d& p : s.hull_points()) robot.radius_ = std::max(robot.radius_, p.norm());
    }
  }
  robot.min_diameter_ = box.sizes().minCoeff();
  return robot;
}

SpatialRobot SpatialRobot::sphere(double radius) {
  SpatialRobot robot(Kind::kSphere, {{Solid::sphere(radius, Eigen::Vector3d::Zero())}});
  robot.radius_ = radius;
  robot.min_diameter_ = 2.0 * radius;
  return robot;
}

SpatialRobot SpatialRobot::scara(ScaraParams params) {
  params.validate();
  SpatialRobot robot(Kind::kScara, scara_links(params));
  double tool_reach = params.link_radius;
  for (const Solid& s : params.tool) {
    for (const Eigen::Vector3d& p : s.hull_points()) tool_reach = std::max(tool_reach, p.head<2>().norm());
  }
  robot.radius_ = params.upper_arm + params.forearm + tool_reach;
  robot.min_diameter_ = 2.0 * params.link_radius;
  for (int i = 0; i < kMaxLinks; ++i) {
    for (int j = i + 2; j < kMaxLinks; ++j) robot.self_pairs_.emplace_back(i, j);
  }
  robot.scara_ = std::move(params);
  return robot;
}

void SpatialRobot::link_poses(const State& s, Eigen::Isometry3d* out) const {
  switch (kind_) {
    case Kind::kRigid: {
      out[0] = translation(s.head<3>());
      out[0].rotate(Eigen::Quaterniond(s[6], s[3], s[4], s[5]).normalized());
      return;
    }
    case Kind::kSphere:
      out[0] = translation(s.head<3>());
      return;
    case Kind::kScara: {
      const ScaraParams& p = scara_;
      const double a1 = s[0] + s[2], a2 = a1 + s[3], a3 = a2 + s[4];
      const Eigen::Vector3d shoulder = p.base + Eigen::Vector3d(0, 0, s[1]);
      const Eigen::Vector3d elbow = shoulder + p.upper_arm * Eigen::Vector3d(std::cos(a1), std::sin(a1), 0);
      const Eigen::Vector3d wrist = elbow + p.forearm * Eigen::Vector3d(std::cos(a2), std::sin(a2), 0);
      out[kColumn] = yawed(p.base, s[0]);
      out[kUpperArm] = yawed(shoulder, a1);
      out[kForearm] = yawed(elbow, a2);
      out[kWrist] = yawed(wrist, a3);
      out[kTool] = yawed(wrist - Eigen::Vector3d(0, 0, p.wrist_length), a3);
      return;
    }
  }
}

Eigen::Vector3d SpatialRobot::reference_point(const State& s) const {
  if (kind_ != Kind::kScara) return s.head<3>();
  std::array<Eigen::Isometry3d, kMaxLinks> poses;
  link_poses(s, poses.data());
  return poses[kTool] * scara_.tip;
}

}  // namespace amp::world
