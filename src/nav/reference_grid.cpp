#include "amp/nav/reference_grid.hpp"

#include <algorithm>
#include <limits>

#include "amp/nav/free_mask.hpp"
#include "amp/nav/nav_world.hpp"

namespace amp::nav {

namespace {
double auto_cell(const NavWorld& world, double cell_size) {
  if (cell_size > 0.0) return cell_size;
  return world.bounds().sizes().maxCoeff() / 256.0;
}
}  // namespace

ReferenceGrid::ReferenceGrid(const NavWorld& world, double radius, double cell_size)
    : mask_(rasterize_free_space(world, auto_cell(world, cell_size), radius)), paths_(mask_.cells()) {}

int ReferenceGrid::cell_near(const Eigen::Vector2d& p) const {
  const FreeMask& m = mask();
  const Eigen::Vector2d q = (p - m.origin()) / m.cell_size();
  const int cx = static_cast<int>(std::floor(q.x())), cy = static_cast<int>(std::floor(q.y()));
  if (m.free(cx, cy)) return m.index(cx, cy);
  int best = -1;
  double best_d = std::numeric_limits<double>::infinity();
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      if (!m.free(cx + dx, cy + dy)) continue;
      const double d = (m.cell_center(cx + dx, cy + dy) - p).squaredNorm();
      if (d < best_d) best_d = d, best = m.index(cx + dx, cy + dy);
    }
  }
  return best;
}

std::vector<std::uint8_t> ReferenceGrid::reachable_from(const Eigen::Vector2d& p) {
  std::vector<std::uint8_t> out(mask().cell_count(), 0);
  const int cell = cell_near(p);
  if (cell < 0) return out;
  paths_.compute(cell);  // distances are symmetric: reachable from p = p reachable from it
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = paths_.distances()[i] < world::GridCostToGo::kUnreachable;
  return out;
}

double ReferenceGrid::shortest_length(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const int ca = cell_near(a), cb = cell_near(b);
  if (ca < 0 || cb < 0) return std::numeric_limits<double>::infinity();
  if (paths_.goal() != cb) paths_.compute(cb);
  const double d = paths_.distance(ca);
  if (d == world::GridCostToGo::kUnreachable) return d;
  return d + (a - mask().cell_center(ca)).norm() + (b - mask().cell_center(cb)).norm();
}

}  // namespace amp::nav
