// PlanarChecker::compute_clearance: exact distance between the placed robot and the obstacles.
#include <cmath>
#include <limits>

#include "amp/world/planar_checker.hpp"
#include "amp/world/polygon_geometry.hpp"

namespace amp::world {

namespace {
Eigen::Vector3d lift(const Eigen::Vector2d& p) { return {p.x(), p.y(), 0.0}; }

// The point at distance `radius` from `center` towards `toward` (the centre itself if they coincide).
Eigen::Vector2d towards(const Eigen::Vector2d& center, double radius, const Eigen::Vector2d& toward) {
  const Eigen::Vector2d d = toward - center;
  const double n = d.norm();
  return n > 0.0 ? Eigen::Vector2d(center + radius * d / n) : center;
}
}  // namespace

Clearance PlanarChecker::compute_clearance(const State& s) const {
  Clearance out;
  if (!check(s)) {
    // In collision, out of bounds or self-colliding: no free distance. Report the reference point.
    const Eigen::Vector2d p = robot_.reference_point(s);
    out.distance = 0.0;
    out.robot_point = out.obstacle_point = lift(p);
    return out;
  }
  // check() placed the robot. Valid means disjoint, so polygon distances are boundary distances.
  out.distance = std::numeric_limits<double>::infinity();
  double best_sq = std::numeric_limits<double>::infinity();
  for (int k = 0; k < static_cast<int>(polygons_.size()); ++k) nearest_to_polygon(k, best_sq, out);
  double best = std::sqrt(best_sq);
  for (int k = 0; k < static_cast<int>(circles_.size()); ++k) nearest_to_circle(k, best, out);
  out.distance = best;
  return out;
}

void PlanarChecker::nearest_to_polygon(int k, double& best_sq, Clearance& out) const {
  const std::span<const Eigen::Vector2d> v = placed(k);
  const Eigen::AlignedBox2d& box = polygon_boxes_[k];
  const auto& edges = world_->edges();
  const auto& obstacles = world_->obstacles();
  Eigen::Vector2d on_robot, on_obstacle;
  // Box distance is a lower bound: skip whole polygons, then single edges, that cannot win.
  const auto nearest_to_edge = [&](const PlanarEdge& e) {
    if (box.squaredExteriorDistance(e.box) >= best_sq) return;
    for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
      const double d = segment_segment_distance_sq(v[j], v[i], e.a, e.b, &on_robot, &on_obstacle);
      if (d < best_sq) {
        best_sq = d;
        out.robot_point = lift(on_robot);
        out.obstacle_point = lift(on_obstacle);
      }
    }
  };
  for (std::size_t p = 0; p < obstacles.polygons.size(); ++p) {
    if (box.squaredExteriorDistance(world_->polygon_boxes()[p]) >= best_sq) continue;
    const int first = polygon_first_edge_[p];
    const int last = first + static_cast<int>(obstacles.polygons[p].vertices.size());
    for (int id = first; id < last; ++id) nearest_to_edge(edges[id]);
  }
  for (int id = world_->first_segment_edge(); id < static_cast<int>(edges.size()); ++id) nearest_to_edge(edges[id]);
  for (std::size_t c = 0; c < obstacles.circles.size(); ++c) {
    const Circle& o = obstacles.circles[c];
    const double lower = std::max(0.0, std::sqrt(box.squaredExteriorDistance(o.center)) - o.radius);
    if (lower * lower >= best_sq) continue;
    const double d = std::sqrt(polygon_boundary_distance_sq(o.center, v, &on_robot)) - o.radius;
    if (d * d < best_sq) {
      best_sq = std::max(0.0, d) * std::max(0.0, d);
      out.robot_point = lift(on_robot);
      out.obstacle_point = lift(towards(o.center, o.radius, on_robot));
    }
  }
}

void PlanarChecker::nearest_to_circle(int k, double& best, Clearance& out) const {
  const Eigen::Vector2d& c = circle_centers_[k];
  const double r = circles_[k].radius;
  const auto& edges = world_->edges();
  const auto& obstacles = world_->obstacles();
  Eigen::Vector2d q;
  const auto nearest_to_edge = [&](const PlanarEdge& e) {
    const double d = std::sqrt(point_segment_distance_sq(c, e.a, e.b, &q)) - r;
    if (d < best) {
      best = std::max(0.0, d);
      out.robot_point = lift(towards(c, r, q));
      out.obstacle_point = lift(q);
    }
  };
  for (std::size_t p = 0; p < obstacles.polygons.size(); ++p) {
    const double lower = std::sqrt(world_->polygon_boxes()[p].squaredExteriorDistance(c)) - r;
    if (lower >= best) continue;
    const int first = polygon_first_edge_[p];
    const int last = first + static_cast<int>(obstacles.polygons[p].vertices.size());
    for (int id = first; id < last; ++id) nearest_to_edge(edges[id]);
  }
  for (int id = world_->first_segment_edge(); id < static_cast<int>(edges.size()); ++id) nearest_to_edge(edges[id]);
  for (const Circle& o : obstacles.circles) {
    const double d = (c - o.center).norm() - r - o.radius;
    if (d < best) {
      best = std::max(0.0, d);
      out.robot_point = lift(towards(c, r, o.center));
      out.obstacle_point = lift(towards(o.center, o.radius, c));
    }
  }
}

}  // namespace amp::world
