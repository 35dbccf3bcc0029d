#pragma once
#include <cmath>
#include <limits>

#include <Eigen/Core>

namespace amp::nav {

// The cells a ray crosses, in order: Amanatides and Woo, "A Fast Voxel Traversal Algorithm for Ray
// Tracing", Eurographics 1987. Grid coordinates: cell (i, j) spans [i, i + 1) x [j, j + 1); the ray
// is origin + t * dir, so with dir = (world direction) / cell side, t is a world distance. A ray
// through a cell corner (equal crossing times) steps both axes at once and says so, so that callers
// can look at the two cells it only touches. No bounds: callers stop when they leave their grid.
class GridTraversal {
 public:
  enum class Crossing { kX, kY, kCorner };
  static constexpr double kNever = std::numeric_limits<double>::infinity();

  // dir must be finite and non-zero.
  GridTraversal(const Eigen::Vector2d& origin, const Eigen::Vector2d& dir)
      : x_(static_cast<int>(std::floor(origin.x()))),
        y_(static_cast<int>(std::floor(origin.y()))),
        step_x_(dir.x() > 0.0 ? 1 : (dir.x() < 0.0 ? -1 : 0)),
        step_y_(dir.y() > 0.0 ? 1 : (dir.y() < 0.0 ? -1 : 0)),
        t_max_x_(first_crossing(origin.x(), dir.x(), x_)),
        t_max_y_(first_crossing(origin.y(), dir.y(), y_)),
        t_delta_x_(step_x_ != 0 ? 1.0 / std::abs(dir.x()) : kNever),
        t_delta_y_(step_y_ != 0 ? 1.0 / std::abs(dir.y()) : kNever) {}

  int x() const { return x_; }
  int y() const { return y_; }
  int step_x() const { return step_x_; }
  int step_y() const { return step_y_; }
  // When the ray leaves the current cell (kNever for a ray that never does).
  double t_exit() const { return std::min(t_max_x_, t_max_y_); }

  // Moves into the next cell, entered at the old t_exit().
  Crossing next() {
    if (t_max_x_ < t_max_y_) {
      x_ += step_x_;
      t_max_x_ += t_delta_x_;
      return Crossing::kX;
    }
    if (t_max_y_ < t_max_x_) {
      y_ += step_y_;
      t_max_y_ += t_delta_y_;
      return Crossing::kY;
    }
    x_ += step_x_;
    y_ += step_y_;
    t_max_x_ += t_delta_x_;
    t_max_y_ += t_delta_y_;
    return Crossing::kCorner;
  }

 private:
  // Time to the first cell border along one axis. A point on a border moving towards lower cells
  // crosses it at once (t = 0): it sits in the upper cell by the half-open convention.
  static double first_crossing(double o, double d, int cell) {
    if (d > 0.0) return (cell + 1.0 - o) / d;
    if (d < 0.0) return (cell - o) / d;
    return kNever;
  }

  int x_, y_;
  int step_x_, step_y_;
  double t_max_x_, t_max_y_;
  double t_delta_x_, t_delta_y_;
};

}  // namespace amp::nav
