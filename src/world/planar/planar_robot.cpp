#include "amp/world/planar_robot.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "amp/core/error.hpp"
#include "amp/world/planar_world.hpp"
#include "amp/world/polygon_geometry.hpp"

namespace amp::world {

namespace {
// Circles enter the minimum-width computation as this many boundary points (a polygon inscribed
// in the circle: the width is under-estimated by at most r * (1 - cos(pi / n)), 0.05% at 64).
constexpr int kCirclePoints = 64;

double body_radius(const Shapes2d& body) {
  double r = 0.0;
  for (const Polygon& p : body.polygons) {
    for (const auto& v : p.vertices) r = std::max(r, v.norm());
  }
  for (const Circle& c : body.circles) r = std::max(r, c.center.norm() + c.radius);
  return r;
}

double body_min_diameter(const Shapes2d& body) {
  if (body.polygons.empty() && body.circles.size() == 1) return 2.0 * body.circles[0].radius;
  std::vector<Eigen::Vector2d> points;
  for (const Polygon& p : body.polygons) points.insert(points.end(), p.vertices.begin(), p.vertices.end());
  for (const Circle& c : body.circles) {
    for (int k = 0; k < kCirclePoints; ++k) {
      const double a = 2.0 * std::numbers::pi * k / kCirclePoints;
      points.push_back(c.center + c.radius * Eigen::Vector2d(std::cos(a), std::sin(a)));
    }
  }
  return minimum_width(points);
}
}  // namespace

PlanarRobot PlanarRobot::rigid(Shapes2d body) {
  if (body.empty()) throw ParameterError("robot: a rigid body needs at least one shape");
  validate_shapes(body, "robot");
  PlanarRobot r;
  r.kind_ = Kind::kRigid;
  r.min_diameter_ = body_min_diameter(body);
  r.radius_ = body_radius(body);
  r.links_.push_back(std::move(body));
  return r;
}

PlanarRobot PlanarRobot::translating(Shapes2d body) {
  if (body.empty()) throw ParameterError("robot: a translating body needs at least one shape");
  validate_shapes(body, "robot", -1.0);
  PlanarRobot r;
  r.kind_ = Kind::kTranslating;
  r.min_diameter_ = body_min_diameter(body);
  r.radius_ = body_radius(body);
  r.links_.push_back(std::move(body));
  return r;
}

PlanarRobot PlanarRobot::fixed_arm(Pose2 base, std::vector<LinkSpec> links) {
  return chain(Kind::kFixedArm, base, std::move(links));
}

PlanarRobot PlanarRobot::free_linkage(std::vector<LinkSpec> links) {
  return chain(Kind::kFreeLinkage, Pose2{}, std::move(links));
}

PlanarRobot PlanarRobot::chain(Kind kind, Pose2 base, std::vector<LinkSpec> links) {
  const int n = static_cast<int>(links.size());
  const int max_links = kind == Kind::kFixedArm ? kMaxDof : kMaxDof - 2;
  if (n < 1 || n > max_links) {
    throw ParameterError("robot.links: need 1 to " + std::to_string(max_links) + " links, got " + std::to_string(n));
  }
  if (!std::isfinite(base.x) || !std::isfinite(base.y) || !std::isfinite(base.theta)) {
    throw ParameterError("robot.base: must be finite");
  }
  PlanarRobot r;
  r.kind_ = kind;
  r.base_ = base;
  r.min_diameter_ = std::numeric_limits<double>::infinity();
  double reach = 0.0;
  for (int i = 0; i < n; ++i) {
    const LinkSpec& l = links[i];
    const std::string name = "robot.links[" + std::to_string(i) + "]";
    if (!(l.length > 0.0) || !std::isfinite(l.length)) throw ParameterError(name + ".length: must be positive");
    if (!(l.width > 0.0) || !std::isfinite(l.width)) throw ParameterError(name + ".width: must be positive");
    if (i > 0 && i < n - 1 && !(l.length > l.width)) {
      throw ParameterError(name + ": a middle link must be longer than it is wide, or its neighbours always collide");
    }
    const double h = 0.5 * l.width;
    Shapes2d shape;
    shape.polygons.push_back(Polygon{{{-h, -h}, {l.length + h, -h}, {l.length + h, h}, {-h, h}}});
    r.links_.push_back(std::move(shape));
    r.min_diameter_ = std::min(r.min_diameter_, l.width);
    r.radius_ = std::max(r.radius_, reach + std::hypot(l.length + h, h));
    reach += l.length;
  }
  r.specs_ = std::move(links);
  return r;
}

int PlanarRobot::state_dimension() const {
  switch (kind_) {
    case Kind::kRigid:
      return 3;
    case Kind::kTranslating:
      return 2;
    case Kind::kFixedArm:
      return link_count();
    case Kind::kFreeLinkage:
      return link_count() + 2;
  }
  return 0;
}

void PlanarRobot::link_poses(const State& s, Pose2* out) const {
  switch (kind_) {
    case Kind::kRigid:
      out[0] = {s[0], s[1], s[2]};
      return;
    case Kind::kTranslating:
      out[0] = {s[0], s[1], 0.0};
      return;
    case Kind::kFixedArm:
    case Kind::kFreeLinkage:
      break;
  }
  const bool arm = kind_ == Kind::kFixedArm;
  // Joint coordinates start at s[0] (arm: joint 0 at the base) or s[3] (linkage: joint 1).
  Pose2 p = arm ? Pose2{base_.x, base_.y, base_.theta + s[0]} : Pose2{s[0], s[1], s[2]};
  out[0] = p;
  const int first_joint = arm ? 1 : 3;
  for (int i = 1; i < link_count(); ++i) {
    const double len = specs_[i - 1].length;
    p.x += len * std::cos(p.theta);
    p.y += len * std::sin(p.theta);
    p.theta += s[first_joint + i - 1];
    out[i] = p;
  }
}

Eigen::Vector2d PlanarRobot::reference_point(const State& s) const {
  Pose2 poses[kMaxDof];
  link_poses(s, poses);
  if (kind_ == Kind::kRigid || kind_ == Kind::kTranslating) return {poses[0].x, poses[0].y};
  const Pose2& last = poses[link_count() - 1];
  const double len = specs_.back().length;
  return {last.x + len * std::cos(last.theta), last.y + len * std::sin(last.theta)};
}

Shapes2d PlanarRobot::outline(const State& s) const {
  Pose2 poses[kMaxDof];
  link_poses(s, poses);
  Shapes2d out;
  for (int i = 0; i < link_count(); ++i) {
    Shapes2d placed = transform_shapes(links_[i], poses[i]);
    out.polygons.insert(out.polygons.end(), placed.polygons.begin(), placed.polygons.end());
    out.circles.insert(out.circles.end(), placed.circles.begin(), placed.circles.end());
  }
  return out;
}

Shapes2d transform_shapes(const Shapes2d& shapes, const Pose2& pose) {
  const double c = std::cos(pose.theta);
  const double s = std::sin(pose.theta);
  Shapes2d out = shapes;
  for (Polygon& p : out.polygons) {
    for (auto& v : p.vertices) v = transform_point(pose, c, s, v);
  }
  for (Circle& k : out.circles) k.center = transform_point(pose, c, s, k.center);
  return out;
}

}  // namespace amp::world
