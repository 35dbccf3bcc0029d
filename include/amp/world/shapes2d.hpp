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
struct Shapes2d {
  std::vector<Polygon> polygons;
  std::vector<Circle> circles;

  bool empty() const { return polygons.empty() && circles.empty(); }
};

// A rigid placement in the plane.
struct Pose2 {
  double x = 0.0, y = 0.0, theta = 0.0;
};

}  // namespace amp::world
