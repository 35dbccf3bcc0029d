#include "amp/nav/free_mask.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "amp/core/error.hpp"
#include "amp/nav/grid_nav_world.hpp"
#include "amp/nav/nav_world.hpp"

namespace amp::nav {

namespace {
constexpr double kMaxCells = double(1 << 28);
// A bounds side that is a whole number of cells up to rounding gets no extra partial cell.
constexpr double kWholeCellSlack = 1e-9;
}  // namespace

FreeMask::FreeMask(int width, int height, double cell_size, Eigen::Vector2d origin)
    : width_(width), height_(height), cell_size_(cell_size), origin_(std::move(origin)) {
  if (width < 1 || height < 1) {
    throw ParameterError("FreeMask: size " + std::to_string(width) + " x " + std::to_string(height) + " has no cell");
  }
  if (!(cell_size > 0.0)) throw ParameterError("FreeMask: cell size must be > 0, got " + std::to_string(cell_size));
  free_.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0);
}

std::size_t FreeMask::free_count() const {
  return static_cast<std::size_t>(std::count(free_.begin(), free_.end(), std::uint8_t{1}));
}

int FreeMask::cell_of(const Eigen::Vector2d& p) const {
  const Eigen::Vector2d g = (p - origin_) / cell_size_;
  if (!(g.x() >= 0.0 && g.y() >= 0.0 && g.x() < width_ && g.y() < height_)) return -1;
  return index(static_cast<int>(g.x()), static_cast<int>(g.y()));
}

FreeMask rasterize_free_space(const NavWorld& world, double cell_size, double radius) {
  if (!(cell_size > 0.0)) throw ParameterError("cell size must be > 0, got " + std::to_string(cell_size));
  if (!(radius >= 0.0)) throw ParameterError("robot radius must be >= 0, got " + std::to_string(radius));
  const Eigen::Vector2d size = world.bounds().sizes() / cell_size;
  const double nx = std::max(1.0, std::ceil(size.x() - kWholeCellSlack));
  const double ny = std::max(1.0, std::ceil(size.y() - kWholeCellSlack));
  if (nx * ny > kMaxCells) {
    throw ParameterError("cell size " + std::to_string(cell_size) + " makes more than 2^28 cells");
  }
  FreeMask mask(static_cast<int>(nx), static_cast<int>(ny), cell_size, world.bounds().min());
  for (int y = 0; y < mask.height(); ++y) {
    for (int x = 0; x < mask.width(); ++x) mask.set_free(x, y, world.disc_free(mask.cell_center(x, y), radius));
  }
  return mask;
}

FreeMask rasterize_free_space(const GridNavWorld& world, double radius) {
  return rasterize_free_space(static_cast<const NavWorld&>(world), world.grid().resolution(), radius);
}

}  // namespace amp::nav
