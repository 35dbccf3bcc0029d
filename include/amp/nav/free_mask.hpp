#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "amp/world/grid_cost_to_go.hpp"

namespace amp::nav {

class NavWorld;
class GridNavWorld;

// A raster of the cells where a robot's centre may be: width x height square cells of side
// cell_size, cell (0, 0) with its outer corner at origin, row-major with row 0 the lowest y.
class FreeMask {
 public:
  // All cells blocked. Throws ParameterError for width/height < 1 or cell_size <= 0.
  FreeMask(int width, int height, double cell_size, Eigen::Vector2d origin = Eigen::Vector2d::Zero());

  int width() const { return width_; }
  int height() const { return height_; }
  double cell_size() const { return cell_size_; }
  const Eigen::Vector2d& origin() const { return origin_; }
  std::size_t cell_count() const { return free_.size(); }

  bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < width_ && y < height_; }
  int index(int x, int y) const { return y * width_ + x; }
  bool free(int x, int y) const { return contains(x, y) && free_[static_cast<std::size_t>(index(x, y))] != 0; }
  bool free(int cell) const { return free_[static_cast<std::size_t>(cell)] != 0; }
  void set_free(int x, int y, bool f) { free_[static_cast<std::size_t>(index(x, y))] = f ? 1 : 0; }
  std::size_t free_count() const;
  // The cells as a search grid (no costs).
  world::GridCells cells() const { return {width_, height_, cell_size_, free_, {}}; }

  Eigen::Vector2d cell_center(int x, int y) const {
    return origin_ + cell_size_ * Eigen::Vector2d(x + 0.5, y + 0.5);
  }
  Eigen::Vector2d cell_center(int cell) const { return cell_center(cell % width_, cell / width_); }
  // The cell holding p, or -1 outside the mask.
  int cell_of(const Eigen::Vector2d& p) const;

 private:
  int width_, height_;
  double cell_size_;
  Eigen::Vector2d origin_;
  std::vector<std::uint8_t> free_;
};

// The world's bounds rasterised into cells of side cell_size from its lower-left corner (a partial
// last column or row is kept); a cell is free iff the disc of radius `radius` at its centre is
// free, i.e. the world inflated by the robot's radius. Throws ParameterError for cell_size <= 0,
// radius < 0 or more than 2^28 cells.
FreeMask rasterize_free_space(const NavWorld& world, double cell_size, double radius);
// A map's own cells (map resolution and origin); free iff the disc at the centre is, which the
// distance transform settles for most cells at once.
FreeMask rasterize_free_space(const GridNavWorld& world, double radius);

}  // namespace amp::nav
