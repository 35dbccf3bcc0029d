#include "amp/nav/policy/waypoint_projection.hpp"

#include <cmath>

#include "amp/core/unicycle_space.hpp"

namespace amp::nav {

namespace {

Eigen::Vector2i step(const GridFrame& f, int a, int b) { return {b % f.width - a % f.width, b / f.width - a / f.width}; }

}  // namespace

std::vector<State> project_to_waypoints(const std::vector<int>& cells, const GridFrame& frame,
                                        const Eigen::Vector2d& start, const Eigen::Vector2d& goal, double cruise) {
  std::vector<State> out;
  if (cells.empty()) return out;
  // Indices of the cells that end a run of equal actions (and the first cell).
  std::vector<std::size_t> ends{0};
  for (std::size_t i = 1; i + 1 < cells.size(); ++i) {
    if (step(frame, cells[i - 1], cells[i]) != step(frame, cells[i], cells[i + 1])) ends.push_back(i);
  }
  if (cells.size() > 1) ends.push_back(cells.size() - 1);
  std::vector<Eigen::Vector2d> points;
  for (std::size_t k = 0; k < ends.size(); ++k) points.push_back(frame.center(cells[ends[k]]));
  points.front() = start;
  if (points.size() == 1) points.push_back(goal);
  points.back() = goal;
  for (std::size_t k = 0; k < points.size(); ++k) {
    // Along the segment this waypoint begins; the last one along the segment it ends.
    const Eigen::Vector2d d = k + 1 < points.size() ? Eigen::Vector2d(points[k + 1] - points[k])
                                                    : Eigen::Vector2d(points[k] - points[k - 1]);
    const double heading = d.squaredNorm() > 0.0 ? std::atan2(d.y(), d.x()) : 0.0;
    out.push_back(core::UnicycleSpace::make_state(points[k].x(), points[k].y(), heading, cruise, 0.0));
  }
  return out;
}

}  // namespace amp::nav
