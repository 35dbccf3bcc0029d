#include "amp/world/occupancy_grid.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "amp/core/error.hpp"

namespace amp::world {

OccupancyGrid::OccupancyGrid(int width, int height, double resolution, Eigen::Vector2d origin)
    : width_(width), height_(height), resolution_(resolution), origin_(origin) {
  if (width < 1 || height < 1) {
    throw ParameterError("occupancy grid: size must be at least 1x1, got " + std::to_string(width) + "x" +
                         std::to_string(height));
  }
  if (!(resolution > 0.0) || !std::isfinite(resolution)) {
    throw ParameterError("occupancy grid: resolution must be positive, got " + std::to_string(resolution));
  }
  if (!origin.allFinite()) throw ParameterError("occupancy grid: origin must be finite");
  cells_.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), CellState::kFree);
  values_.assign(cells_.size(), 0);
}

Eigen::Vector2i OccupancyGrid::world_to_cell(const Eigen::Vector2d& p) const {
  const Eigen::Vector2d g = world_to_grid(p);
  return {static_cast<int>(std::floor(g.x())), static_cast<int>(std::floor(g.y()))};
}

Eigen::Vector2d OccupancyGrid::cell_center(int cx, int cy) const {
  return origin_ + resolution_ * Eigen::Vector2d(cx + 0.5, cy + 0.5);
}

Eigen::AlignedBox2d OccupancyGrid::cell_box(int cx, int cy) const {
  const Eigen::Vector2d lo = origin_ + resolution_ * Eigen::Vector2d(cx, cy);
  return {lo, lo + Eigen::Vector2d::Constant(resolution_)};
}

Eigen::AlignedBox2d OccupancyGrid::extent() const {
  return {origin_, origin_ + resolution_ * Eigen::Vector2d(width_, height_)};
}

std::size_t OccupancyGrid::count(CellState s) const {
  return static_cast<std::size_t>(std::count(cells_.begin(), cells_.end(), s));
}

}  // namespace amp::world
