#pragma once
// Small test-only worlds for the roadmap tests: a point robot in R2 among axis-aligned boxes, and a
// planar two-link arm (continuous + revolute joint) among the same boxes. Exact and simple, so the
// tests can compute expected answers independently.
#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "amp/core/joint_space.hpp"
#include "amp/world/environment.hpp"
#include "amp/world/problem.hpp"
#include "amp/world/solid_mesh.hpp"

namespace amp::roadmap::test {

struct Box {
  double x0, y0, x1, y1;
  bool contains(const Eigen::Vector2d& p) const { return p.x() >= x0 && p.x() <= x1 && p.y() >= y0 && p.y() <= y1; }
  double distance(const Eigen::Vector2d& p) const {
    const double dx = std::max({x0 - p.x(), 0.0, p.x() - x1});
    const double dy = std::max({y0 - p.y(), 0.0, p.y() - y1});
    return std::hypot(dx, dy);
  }
};

// Robot kinematics: the points of the robot that must stay out of the boxes.
enum class RobotKind { kPoint, kArm };

inline constexpr double kArmLink = 2.0;
inline constexpr int kArmPointsPerLink = 8;
inline const Eigen::Vector2d kArmBase(5.0, 5.0);

inline void robot_points(RobotKind kind, const State& s, std::vector<Eigen::Vector2d>& out) {
  out.clear();
  if (kind == RobotKind::kPoint) {
    out.emplace_back(s[0], s[1]);
    return;
  }
  const Eigen::Vector2d elbow = kArmBase + kArmLink * Eigen::Vector2d(std::cos(s[0]), std::sin(s[0]));
  const Eigen::Vector2d tip = elbow + kArmLink * Eigen::Vector2d(std::cos(s[0] + s[1]), std::sin(s[0] + s[1]));
  for (int i = 1; i <= kArmPointsPerLink; ++i) {
    const double t = static_cast<double>(i) / kArmPointsPerLink;
    out.push_back(kArmBase + t * (elbow - kArmBase));
    out.push_back(elbow + t * (tip - elbow));
  }
}

// Counts like every checker; optionally records every state it is asked about (for order tests).
class BoxChecker final : public world::ValidityChecker {
 public:
  BoxChecker(core::Counters& c, const std::vector<Box>& boxes, RobotKind kind, std::vector<State>* record)
      : ValidityChecker(c), boxes_(&boxes), kind_(kind), record_(record) {}

 private:
  bool check(const State& s) const override {
    if (record_ != nullptr) record_->push_back(s);
    robot_points(kind_, s, points_);
    for (const auto& p : points_) {
      if (kind_ == RobotKind::kPoint && (p.x() < 0 || p.x() > 10 || p.y() < 0 || p.y() > 10)) return false;
      for (const Box& b : *boxes_) {
        if (b.contains(p)) return false;
      }
    }
    return true;
  }
  world::Clearance compute_clearance(const State& s) const override {
    robot_points(kind_, s, points_);
    world::Clearance c;
    c.distance = 1e9;
    for (const auto& p : points_) {
      for (const Box& b : *boxes_) c.distance = std::min(c.distance, b.distance(p));
    }
    return c;
  }
  // The robot is its points: each must stay out of the boxes (and, for the point, in the square).
  double compute_free_radius(const State& s) const override {
    if (!check(s)) return 0.0;
    double r = compute_clearance(s).distance;
    if (kind_ == RobotKind::kPoint) r = std::min({r, s[0], s[1], 10.0 - s[0], 10.0 - s[1]});
    return r;
  }
  // Joint 0 turns both links (reach 2 links), joint 1 the outer one.
  double compute_motion_bound(const State& a, const State& b) const override {
    if (kind_ == RobotKind::kPoint) return std::hypot(b[0] - a[0], b[1] - a[1]);
    return 2 * kArmLink * std::abs(core::angle_difference(a[0], b[0])) + kArmLink * std::abs(b[1] - a[1]);
  }

  const std::vector<Box>* boxes_;
  RobotKind kind_;
  std::vector<State>* record_;
  mutable std::vector<Eigen::Vector2d> points_;
};

class BoxEnvironment final : public world::Environment {
 public:
  BoxEnvironment(std::vector<Box> boxes, RobotKind kind) : boxes_(std::move(boxes)), kind_(kind) {}

  // Checkers made while `record` is set append every checked state to it.
  void set_record(std::vector<State>* record) { record_ = record; }

  int workspace_dimension() const override { return 2; }
  std::unique_ptr<world::ValidityChecker> make_checker(core::Counters& counters) const override {
    return std::make_unique<BoxChecker>(counters, boxes_, kind_, record_);
  }
  Eigen::AlignedBox3d workspace_bounds() const override {
    return Eigen::AlignedBox3d(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(10, 10, 0));
  }
  world::Outline obstacle_outline() const override { return {}; }
  world::Shapes2d robot_outline(const State&) const override { return {}; }
  // The boxes and the robot raised as every 2-D world is (flat_heights); the point as a small disc,
  // the arm's links as thin bars from their joints along +x.
  world::SceneModel scene_model() const override {
    const Eigen::AlignedBox2d extent(Eigen::Vector2d(0, 0), Eigen::Vector2d(10, 10));
    const world::FlatHeights h = world::flat_heights(extent);
    world::SceneModel model;
    model.flat = true;
    model.bounds = world::flat_bounds(extent, h);
    for (const Box& b : boxes_) {
      world::Polygon p{{{b.x0, b.y0}, {b.x1, b.y0}, {b.x1, b.y1}, {b.x0, b.y1}}};
      model.obstacles.push_back(world::extrude_shapes({{p}, {}}, 0.0, h.obstacles, h.wall_thickness));
    }
    if (kind_ == RobotKind::kPoint) {
      const world::Circle point{Eigen::Vector2d::Zero(), 0.0};
      model.robot_links.push_back(world::extrude_shapes({{}, {point}}, 0.0, h.robot, h.wall_thickness));
      model.link_names = {"body"};
      return model;
    }
    const world::Segment bar{Eigen::Vector2d::Zero(), Eigen::Vector2d(kArmLink, 0.0)};
    for (const char* name : {"link 0", "link 1"}) {
      model.robot_links.push_back(world::extrude_shapes({{}, {}, {bar}}, 0.0, h.robot, h.wall_thickness));
      model.link_names.emplace_back(name);
    }
    return model;
  }
  void robot_link_poses(const State& s, std::vector<Eigen::Isometry3d>& out) const override {
    if (kind_ == RobotKind::kPoint) {
      out = {world::lift_pose({s[0], s[1], 0.0})};
      return;
    }
    const Eigen::Vector2d elbow = kArmBase + kArmLink * Eigen::Vector2d(std::cos(s[0]), std::sin(s[0]));
    out = {world::lift_pose({kArmBase.x(), kArmBase.y(), s[0]}),
           world::lift_pose({elbow.x(), elbow.y(), s[0] + s[1]})};
  }
  Eigen::Vector3d reference_point(const State& s) const override {
    robot_points(kind_, s, points_);
    return Eigen::Vector3d(points_.back().x(), points_.back().y(), 0.0);
  }
  double robot_min_diameter() const override { return 0.0; }
  double robot_radius() const override { return kind_ == RobotKind::kArm ? 2 * kArmLink : 0.0; }

 private:
  std::vector<Box> boxes_;
  RobotKind kind_;
  std::vector<State>* record_ = nullptr;
  mutable std::vector<Eigen::Vector2d> points_;
};

inline State state2(double a, double b) {
  State s(2);
  s << a, b;
  return s;
}

// Point robot in [0,10]^2; a wall at x in [4.5, 5.5] with a gap y in [4.6, 5.4] (or none: unsolvable).
inline world::Problem point_problem(bool with_gap) {
  std::vector<Box> boxes;
  if (with_gap) {
    boxes = {{4.5, 0.0, 5.5, 4.6}, {4.5, 5.4, 5.5, 10.0}};
  } else {
    boxes = {{4.5, 0.0, 5.5, 10.0}};
  }
  world::Problem p;
  p.name = with_gap ? "narrow_gap" : "blocked";
  p.space = std::make_shared<core::JointSpace>(core::make_rn_space({0, 0}, {10, 10}));
  p.environment = std::make_shared<BoxEnvironment>(boxes, RobotKind::kPoint);
  p.seeds = {state2(1, 2), state2(9, 2)};  // the straight line is blocked: through the gap
  return p;
}

// Two-link arm at (5,5) (joint 0 continuous, joint 1 revolute in [-2.8, 2.8]) between two boxes:
// it must swing its tip from one side of an obstacle to the other.
inline world::Problem arm_problem() {
  std::vector<Box> boxes = {{8.2, 4.0, 9.5, 6.0}, {0.5, 0.5, 2.0, 2.0}};
  world::Problem p;
  p.name = "arm";
  p.space = std::make_shared<core::JointSpace>(
      "linkage", std::vector<core::Joint>{{"j0", core::JointKind::kContinuous, -std::numbers::pi, std::numbers::pi, 2.0},
                                          {"j1", core::JointKind::kRevolute, -2.8, 2.8, 1.0}});
  p.environment = std::make_shared<BoxEnvironment>(boxes, RobotKind::kArm);
  p.seeds = {state2(0.6, 0.0), state2(-0.6, 0.0)};
  return p;
}

}  // namespace amp::roadmap::test
