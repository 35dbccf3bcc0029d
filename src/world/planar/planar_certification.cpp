// PlanarChecker's part of edge certification (roadmap::EdgeCertifier): how far the robot is from
// becoming invalid, and how far its points can travel along an edge.
#include <algorithm>
#include <cmath>
#include <limits>

#include "amp/core/joint_space.hpp"
#include "amp/world/planar_checker.hpp"
#include "amp/world/polygon_geometry.hpp"

namespace amp::world {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

// Distance from a box inside `bounds` to the outside of `bounds`.
double inner_margin(const Eigen::AlignedBox2d& box, const Eigen::AlignedBox2d& bounds) {
  const Eigen::Vector2d lo = box.min() - bounds.min(), hi = bounds.max() - box.max();
  return std::max(0.0, std::min(lo.minCoeff(), hi.minCoeff()));
}

double polygon_polygon_distance(std::span<const Eigen::Vector2d> a, std::span<const Eigen::Vector2d> b) {
  double best = kInf;
  for (std::size_t i = 0, j = a.size() - 1; i < a.size(); j = i++) {
    for (std::size_t k = 0, l = b.size() - 1; k < b.size(); l = k++) {
      best = std::min(best, segment_segment_distance_sq(a[j], a[i], b[l], b[k], nullptr, nullptr));
    }
  }
  return std::sqrt(best);
}
}  // namespace

Eigen::Vector2d PlanarChecker::reference_point_placed() const {
  if (robot_.kind() == PlanarRobot::Kind::kRigid || robot_.kind() == PlanarRobot::Kind::kTranslating) {
    return {poses_[0].x, poses_[0].y};
  }
  const Pose2& last = poses_.back();
  const double len = robot_.link_specs().back().length;
  return {last.x + len * std::cos(last.theta), last.y + len * std::sin(last.theta)};
}

double PlanarChecker::bounds_margin() const {
  const Eigen::AlignedBox2d& bounds = world_->bounds();
  if (bounds_check_ == PlanarBoundsCheck::kReferencePoint) {
    const Eigen::Vector2d p = reference_point_placed();
    return inner_margin(Eigen::AlignedBox2d(p, p), bounds);
  }
  double best = kInf;
  for (const auto& b : link_boxes_) best = std::min(best, inner_margin(b, bounds));
  return best;
}

// Valid states have disjoint non-adjacent links, so boundary distances are the link distances.
double PlanarChecker::self_distance() const {
  double best = kInf;
  const int n = robot_.link_count();
  for (int i = 0; i < n; ++i) {
    for (int j = i + 2; j < n; ++j) {
      const LinkRange& a = link_ranges_[i];
      const LinkRange& b = link_ranges_[j];
      for (int p = a.polygon_begin; p < a.polygon_end; ++p) {
        for (int q = b.polygon_begin; q < b.polygon_end; ++q) best = std::min(best, polygon_polygon_distance(placed(p), placed(q)));
        for (int q = b.circle_begin; q < b.circle_end; ++q) {
          const double d = std::sqrt(polygon_boundary_distance_sq(circle_centers_[q], placed(p), nullptr)) - circles_[q].radius;
          best = std::min(best, d);
        }
      }
      for (int p = a.circle_begin; p < a.circle_end; ++p) {
        for (int q = b.polygon_begin; q < b.polygon_end; ++q) {
          const double d = std::sqrt(polygon_boundary_distance_sq(circle_centers_[p], placed(q), nullptr)) - circles_[p].radius;
          best = std::min(best, d);
        }
        for (int q = b.circle_begin; q < b.circle_end; ++q) {
          best = std::min(best, (circle_centers_[p] - circle_centers_[q]).norm() - circles_[p].radius - circles_[q].radius);
        }
      }
    }
  }
  return std::max(0.0, best);
}

double PlanarChecker::compute_free_radius(const State& s) const {
  const double obstacles = compute_clearance(s).distance;  // 0 unless s is valid; places the robot
  if (!(obstacles > 0.0)) return 0.0;
  double r = std::min(obstacles, bounds_margin());
  // Two links may approach each other at twice the speed of either.
  if (robot_.has_self_collision()) r = std::min(r, 0.5 * self_distance());
  return r;
}

double PlanarChecker::compute_motion_bound(const State& a, const State& b) const {
  // Angles: rigid bodies' and linkages' headings are continuous joints (the short way round);
  // arm joints may be revolute (the straight way), so |b - a| bounds both readings.
  const auto turn = [&](int i, bool continuous) {
    return continuous ? std::abs(core::angle_difference(a[i], b[i])) : std::abs(b[i] - a[i]);
  };
  const auto shift = [&](int i) { return std::hypot(b[i] - a[i], b[i + 1] - a[i + 1]); };
  switch (robot_.kind()) {
    case PlanarRobot::Kind::kTranslating:
      return shift(0);
    case PlanarRobot::Kind::kRigid:
      return shift(0) + joint_reach_[0] * turn(2, true);
    case PlanarRobot::Kind::kFixedArm: {
      double bound = 0.0;
      for (int j = 0; j < robot_.link_count(); ++j) bound += joint_reach_[j] * turn(j, false);
      return bound;
    }
    case PlanarRobot::Kind::kFreeLinkage: {
      double bound = shift(0) + joint_reach_[0] * turn(2, true);
      for (int j = 1; j < robot_.link_count(); ++j) bound += joint_reach_[j] * turn(j + 2, false);
      return bound;
    }
  }
  return kInf;
}

}  // namespace amp::world
