#include "amp/world/grid_environment.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "amp/core/error.hpp"
#include "amp/core/joint_space.hpp"

namespace amp::world {

namespace {

Eigen::Vector2d transform(const Eigen::Vector2d& p, double x, double y, double c, double s) {
  return {x + c * p.x() - s * p.y(), y + s * p.x() + c * p.y()};
}

// Smallest extent of a polygon across its edge directions (its width for a convex polygon).
double polygon_width(const Polygon& poly) {
  double best = std::numeric_limits<double>::infinity();
  const auto& v = poly.vertices;
  for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
    const Eigen::Vector2d e = v[i] - v[j];
    if (e.norm() == 0.0) continue;
    const Eigen::Vector2d n(-e.y() / e.norm(), e.x() / e.norm());
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const auto& p : v) {
      lo = std::min(lo, n.dot(p));
      hi = std::max(hi, n.dot(p));
    }
    best = std::min(best, hi - lo);
  }
  return best;
}

// A point is free iff it lies inside the map and in no closed blocked square: strictly positive
// distance to every blocked square and to the map's outside (a point on a blocked square's edge
// touches it).
class PointChecker final : public ValidityChecker {
 public:
  PointChecker(const GridObstacles& obstacles, core::Counters& counters)
      : ValidityChecker(counters), obstacles_(obstacles) {}

 private:
  bool check(const State& s) const override {
    Eigen::Vector2d q;
    return obstacles_.point_distance({s[0], s[1]}, q) > 0.0;
  }
  Clearance compute_clearance(const State& s) const override {
    Eigen::Vector2d q;
    const double d = obstacles_.point_distance({s[0], s[1]}, q);
    return {d, {s[0], s[1], 0.0}, {q.x(), q.y(), 0.0}};
  }
  double compute_free_radius(const State& s) const override { return check(s) ? compute_clearance(s).distance : 0.0; }
  double compute_motion_bound(const State& a, const State& b) const override {
    return std::hypot(b[0] - a[0], b[1] - a[1]);
  }

  const GridObstacles& obstacles_;
};

class DiscChecker final : public ValidityChecker {
 public:
  DiscChecker(const GridObstacles& obstacles, double radius, core::Counters& counters)
      : ValidityChecker(counters), obstacles_(obstacles), radius_(radius) {}

 private:
  bool check(const State& s) const override { return obstacles_.disc_free({s[0], s[1]}, radius_); }

  Clearance compute_clearance(const State& s) const override {
    const Eigen::Vector2d p(s[0], s[1]);
    Eigen::Vector2d q;
    const double d = obstacles_.point_distance(p, q);
    const Eigen::Vector2d dir = d > 0.0 ? Eigen::Vector2d((q - p) / d) : Eigen::Vector2d::Zero();
    const Eigen::Vector2d rp = p + radius_ * dir;
    return {std::max(0.0, d - radius_), {rp.x(), rp.y(), 0.0}, {q.x(), q.y(), 0.0}};
  }

  // The EDT distances are exact to the blocked squares and the map's outside.
  double compute_free_radius(const State& s) const override { return check(s) ? compute_clearance(s).distance : 0.0; }
  double compute_motion_bound(const State& a, const State& b) const override {
    return std::hypot(b[0] - a[0], b[1] - a[1]);
  }

  const GridObstacles& obstacles_;
  double radius_;
};

// A rigid body of polygons and circles; its world-frame vertices go to a buffer sized once.
class RigidChecker final : public ValidityChecker {
 public:
  RigidChecker(const GridObstacles& obstacles, const Shapes2d& body, core::Counters& counters)
      : ValidityChecker(counters), obstacles_(obstacles), body_(body) {
    std::size_t most = 0;
    for (const auto& poly : body_.polygons) most = std::max(most, poly.vertices.size());
    scratch_.resize(most);
    for (const auto& poly : body_.polygons) {
      for (const auto& v : poly.vertices) reach_ = std::max(reach_, v.norm());
    }
    for (const auto& circle : body_.circles) reach_ = std::max(reach_, circle.center.norm() + circle.radius);
  }

 private:
  // Places polygon k at state s into scratch_.
  int place(const Polygon& poly, double x, double y, double c, double sn) const {
    const int n = static_cast<int>(poly.vertices.size());
    for (int i = 0; i < n; ++i) scratch_[static_cast<std::size_t>(i)] = transform(poly.vertices[i], x, y, c, sn);
    return n;
  }

  bool check(const State& s) const override {
    const double c = std::cos(s[2]), sn = std::sin(s[2]);
    for (const auto& circle : body_.circles) {
      if (!obstacles_.disc_free(transform(circle.center, s[0], s[1], c, sn), circle.radius)) return false;
    }
    for (const auto& poly : body_.polygons) {
      const int n = place(poly, s[0], s[1], c, sn);
      if (!obstacles_.polygon_free(scratch_.data(), n)) return false;
    }
    return true;
  }

  Clearance compute_clearance(const State& s) const override {
    const double c = std::cos(s[2]), sn = std::sin(s[2]);
    Clearance best;
    best.distance = std::numeric_limits<double>::infinity();
    auto keep = [&best](double d, const Eigen::Vector2d& rp, const Eigen::Vector2d& op) {
      if (d < best.distance) best = {d, {rp.x(), rp.y(), 0.0}, {op.x(), op.y(), 0.0}};
    };
    for (const auto& circle : body_.circles) {
      const Eigen::Vector2d p = transform(circle.center, s[0], s[1], c, sn);
      Eigen::Vector2d q;
      const double d = obstacles_.point_distance(p, q);
      const Eigen::Vector2d dir = d > 0.0 ? Eigen::Vector2d((q - p) / d) : Eigen::Vector2d::Zero();
      keep(std::max(0.0, d - circle.radius), p + circle.radius * dir, q);
    }
    for (const auto& poly : body_.polygons) {
      const int n = place(poly, s[0], s[1], c, sn);
      Eigen::Vector2d rp, op;
      const double d = obstacles_.polygon_distance(scratch_.data(), n, rp, op);
      keep(d, rp, op);
    }
    return best;
  }

  double compute_free_radius(const State& s) const override { return check(s) ? compute_clearance(s).distance : 0.0; }
  // State (x, y, theta), theta continuous (the short way round, as JointSpace interpolates it).
  double compute_motion_bound(const State& a, const State& b) const override {
    return std::hypot(b[0] - a[0], b[1] - a[1]) + reach_ * std::abs(core::angle_difference(a[2], b[2]));
  }

  const GridObstacles& obstacles_;
  const Shapes2d& body_;
  double reach_ = 0.0;  // farthest body point from the reference point
  mutable std::vector<Eigen::Vector2d> scratch_;
};

}  // namespace

GridEnvironment::GridEnvironment(std::shared_ptr<const OccupancyGrid> grid, GridRobot robot)
    : obstacles_(std::move(grid)), robot_(std::move(robot)) {
  if (robot_.kind == GridRobot::Kind::kPoint) return;  // no size: diameter and radius 0
  if (robot_.kind == GridRobot::Kind::kDisc) {
    if (!(robot_.radius > 0.0) || !std::isfinite(robot_.radius)) {
      throw ParameterError("disc robot: radius must be positive, got " + std::to_string(robot_.radius));
    }
    min_diameter_ = 2.0 * robot_.radius;
    radius_ = robot_.radius;
    return;
  }
  if (robot_.body.empty()) throw ParameterError("rigid robot: the body has no shapes");
  min_diameter_ = std::numeric_limits<double>::infinity();
  for (const auto& poly : robot_.body.polygons) {
    if (poly.vertices.size() < 3) {
      throw ParameterError("rigid robot: a polygon needs at least 3 vertices, got " +
                           std::to_string(poly.vertices.size()));
    }
    min_diameter_ = std::min(min_diameter_, polygon_width(poly));
    for (const auto& v : poly.vertices) radius_ = std::max(radius_, v.norm());
  }
  for (const auto& circle : robot_.body.circles) {
    if (!(circle.radius > 0.0)) {
      throw ParameterError("rigid robot: circle radius must be positive, got " + std::to_string(circle.radius));
    }
    min_diameter_ = std::min(min_diameter_, 2.0 * circle.radius);
    radius_ = std::max(radius_, circle.center.norm() + circle.radius);
  }
}

std::unique_ptr<ValidityChecker> GridEnvironment::make_checker(core::Counters& counters) const {
  if (robot_.kind == GridRobot::Kind::kDisc) {
    return std::make_unique<DiscChecker>(obstacles_, robot_.radius, counters);
  }
  if (robot_.kind == GridRobot::Kind::kPoint) return std::make_unique<PointChecker>(obstacles_, counters);
  return std::make_unique<RigidChecker>(obstacles_, robot_.body, counters);
}

Eigen::AlignedBox3d GridEnvironment::workspace_bounds() const {
  const Eigen::AlignedBox2d e = grid().extent();
  return {Eigen::Vector3d(e.min().x(), e.min().y(), 0.0), Eigen::Vector3d(e.max().x(), e.max().y(), 0.0)};
}

Outline GridEnvironment::obstacle_outline() const {
  Outline out;
  out.grid = &grid();
  return out;
}

Shapes2d GridEnvironment::robot_outline(const State& s) const {
  Shapes2d out;
  if (robot_.kind != GridRobot::Kind::kRigid) {
    out.circles.push_back({Eigen::Vector2d(s[0], s[1]), robot_.radius});  // radius 0 for a point
    return out;
  }
  const double c = std::cos(s[2]), sn = std::sin(s[2]);
  for (const auto& poly : robot_.body.polygons) {
    Polygon placed;
    for (const auto& v : poly.vertices) placed.vertices.push_back(transform(v, s[0], s[1], c, sn));
    out.polygons.push_back(std::move(placed));
  }
  for (const auto& circle : robot_.body.circles) {
    out.circles.push_back({transform(circle.center, s[0], s[1], c, sn), circle.radius});
  }
  return out;
}

Eigen::Vector3d GridEnvironment::reference_point(const State& s) const { return {s[0], s[1], 0.0}; }

}  // namespace amp::world
