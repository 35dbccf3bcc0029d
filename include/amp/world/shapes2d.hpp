#pragma once
#include <vector>

#include <Eigen/Core>

namespace amp::world {

// A simple polygon (convex or not, either orientation), vertices in order, not closed (the last
// vertex joins the first).
struct Polygon {
  std::vector<Eigen::Vector2d> vertices;
};

struct Circle {
  Eigen::Vector2d center = Eigen::Vector2d::Zero();
  double radius = 0.0;
};

// A set of planar shapes: an obstacle field, one robot link, or a drawing.
// A wall of no thickness: what a vertical face of a 3-D world leaves in the plane (OMPL.app's
// 2-D problems, which FCL checks surface against surface). Obstacles only.
struct Segment {
  Eigen::Vector2d a = Eigen::Vector2d::Zero();
  Eigen::Vector2d b = Eigen::Vector2d::Zero();
};

struct Shapes2d {
  std::vector<Polygon> polygons;
  std::vector<Circle> circles;
  std::vector<Segment> segments{};  // initialised so that {polygons, circles} still builds a Shapes2d

  bool empty() const { return polygons.empty() && circles.empty() && segments.empty(); }
};

// A rigid placement in the plane.
struct Pose2 {
  double x = 0.0, y = 0.0, theta = 0.0;
};

}  // namespace amp::world
