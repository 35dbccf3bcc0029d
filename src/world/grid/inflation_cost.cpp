#include "amp/world/inflation_cost.hpp"

#include <cmath>
#include <string>

#include "amp/core/error.hpp"
#include "amp/world/grid_environment.hpp"

namespace amp::world {

void InflationSettings::validate() const {
  auto check = [](double v, const char* name) {
    if (!(v >= 0.0) || !std::isfinite(v)) {
      throw ParameterError(std::string(name) + " must be >= 0 and finite, got " + std::to_string(v));
    }
  };
  check(inscribed_radius, "inscribed_radius");
  check(inflation_radius, "inflation_radius");
  check(cost_scaling_factor, "cost_scaling_factor");
  check(penalty, "penalty");
  if (penalty > GridCostToGo::kMaxCellCost) {
    throw ParameterError("penalty must be <= " + std::to_string(GridCostToGo::kMaxCellCost) + ", got " +
                         std::to_string(penalty));
  }
}

GridCells inflate(const GridObstacles& obstacles, const InflationSettings& s) {
  s.validate();
  const OccupancyGrid& grid = obstacles.grid();
  GridCells out;
  out.width = grid.width();
  out.height = grid.height();
  out.cell_size = grid.resolution();
  const std::size_t n = static_cast<std::size_t>(out.width) * static_cast<std::size_t>(out.height);
  out.free.assign(n, 0);
  const bool costs = s.inflation_radius > s.inscribed_radius && s.penalty > 0.0;
  if (costs) out.cost.assign(n, 0.0);
  for (int y = 0; y < out.height; ++y) {
    for (int x = 0; x < out.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(out.width) + static_cast<std::size_t>(x);
      if (grid.blocked(x, y)) continue;
      const Eigen::Vector2d c = grid.cell_center(x, y);
      if (s.inscribed_radius > 0.0 && !obstacles.disc_free(c, s.inscribed_radius)) continue;
      out.free[i] = 1;
      if (!costs) continue;
      // Most free cells are far from every wall; the cheap disc test proves their cost is 0 without
      // an exact distance query (the margin keeps d == inflation_radius on the exact path).
      if (obstacles.disc_free(c, s.inflation_radius * (1.0 + 1e-12) + 1e-12)) continue;
      Eigen::Vector2d nearest;
      const double d = obstacles.point_distance(c, nearest);
      if (d <= s.inflation_radius) {
        out.cost[i] = s.penalty * std::exp(-s.cost_scaling_factor * std::max(0.0, d - s.inscribed_radius));
      }
    }
  }
  return out;
}

}  // namespace amp::world
