#include "amp/nav/grid_nav_world.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "amp/core/error.hpp"
#include "amp/nav/grid_traversal.hpp"
#include "amp/nav/world_event.hpp"
#include "amp/world/polygon_geometry.hpp"

namespace amp::nav {

namespace {

// A shape changes a cell only when it overlaps the cell with positive area: the cell is shrunk by
// this fraction of its side before the (closed) overlap test, so a box drawn on cell borders does
// not spill into its neighbours.
constexpr double kCellShrink = 1e-9;

std::shared_ptr<const world::OccupancyGrid> checked(std::shared_ptr<const world::OccupancyGrid> grid) {
  if (!grid) throw ParameterError("GridNavWorld: no grid");
  return grid;
}

std::string rect_text(const CellRect& r) {
  return "[" + std::to_string(r.x0) + ", " + std::to_string(r.y0) + ", " + std::to_string(r.x1) + ", " +
         std::to_string(r.y1) + "]";
}

}  // namespace

GridNavWorld::GridNavWorld(std::shared_ptr<const world::OccupancyGrid> grid)
    : obstacles_(checked(std::move(grid))), extent_(obstacles_.grid().extent()) {}

bool GridNavWorld::blocked_or_outside(int cx, int cy) const {
  const world::OccupancyGrid& g = grid();
  return !g.contains_cell(cx, cy) || g.blocked(cx, cy);
}

bool GridNavWorld::touches_blocked(const Eigen::Vector2d& g) const {
  const world::OccupancyGrid& map = grid();
  if (!(g.x() >= 0.0 && g.y() >= 0.0 && g.x() <= map.width() && g.y() <= map.height())) return true;
  const int cx = static_cast<int>(std::floor(g.x())), cy = static_cast<int>(std::floor(g.y()));
  // A point on a cell border also belongs to the closed square on the other side.
  const int lx = g.x() == cx ? cx - 1 : cx, ly = g.y() == cy ? cy - 1 : cy;
  for (int y = ly; y <= cy; ++y) {
    for (int x = lx; x <= cx; ++x) {
      if (blocked_or_outside(x, y)) return true;
    }
  }
  return false;
}

NearestObstacle GridNavWorld::nearest_obstacle(const Eigen::Vector2d& p) const {
  NearestObstacle out;
  out.distance = obstacles_.point_distance(p, out.point);
  return out;
}

double GridNavWorld::ray_cast(const Eigen::Vector2d& p, const Eigen::Vector2d& dir, double max_range) const {
  if (!p.allFinite() || !dir.allFinite() || dir.isZero(0.0)) return 0.0;
  const world::OccupancyGrid& map = grid();
  const Eigen::Vector2d g = map.world_to_grid(p);
  if (touches_blocked(g)) return 0.0;
  GridTraversal walk(g, dir / map.resolution());
  // A ray running exactly along a grid line touches the squares on both sides of it.
  const bool along_row_line = dir.y() == 0.0 && g.y() == std::floor(g.y());
  const bool along_column_line = dir.x() == 0.0 && g.x() == std::floor(g.x());
  for (;;) {
    const double t = walk.t_exit();
    if (t >= max_range) return max_range;
    const int px = walk.x(), py = walk.y();
    const GridTraversal::Crossing crossing = walk.next();
    const int x = walk.x(), y = walk.y();
    bool hit = blocked_or_outside(x, y);
    // Through a corner: the two cells beside the diagonal step touch the ray at that corner.
    if (crossing == GridTraversal::Crossing::kCorner) {
      hit = hit || blocked_or_outside(px + walk.step_x(), py) || blocked_or_outside(px, py + walk.step_y());
    }
    if (along_row_line) hit = hit || blocked_or_outside(x, y - 1);
    if (along_column_line) hit = hit || blocked_or_outside(x - 1, y);
    if (hit) return t;
  }
}

std::shared_ptr<const NavWorld> GridNavWorld::changed(const ObstacleChange& change) const {
  if (!change.shapes.segments.empty()) throw ParameterError("segment walls cannot appear or vanish on a map");
  auto map = std::make_shared<world::OccupancyGrid>(grid());
  const world::CellState state =
      change.action == ObstacleChange::Action::kAppear ? world::CellState::kOccupied : world::CellState::kFree;
  for (const CellRect& r : change.cells) {
    if (r.x0 > r.x1 || r.y0 > r.y1 || !map->contains_cell(r.x0, r.y0) || !map->contains_cell(r.x1, r.y1)) {
      throw ParameterError("cells " + rect_text(r) + " are not a rectangle inside the " + std::to_string(map->width()) +
                           " x " + std::to_string(map->height()) + " map");
    }
    for (int y = r.y0; y <= r.y1; ++y) {
      for (int x = r.x0; x <= r.x1; ++x) map->set_state(x, y, state);
    }
  }
  // Shapes act on the cells they overlap; only the cells under their bounding boxes are tested.
  const auto for_cells_under = [&](const Eigen::AlignedBox2d& box, auto&& overlaps) {
    const Eigen::Vector2i lo = map->world_to_cell(box.min()).cwiseMax(Eigen::Vector2i::Zero());
    const Eigen::Vector2i hi = map->world_to_cell(box.max()).cwiseMin(Eigen::Vector2i(map->width() - 1, map->height() - 1));
    const Eigen::Vector2d shrink = Eigen::Vector2d::Constant(kCellShrink * map->resolution());
    for (int y = lo.y(); y <= hi.y(); ++y) {
      for (int x = lo.x(); x <= hi.x(); ++x) {
        const Eigen::AlignedBox2d c = map->cell_box(x, y);
        if (overlaps(Eigen::AlignedBox2d(c.min() + shrink, c.max() - shrink))) map->set_state(x, y, state);
      }
    }
  };
  for (const world::Polygon& poly : change.shapes.polygons) {
    for_cells_under(world::bounding_box(poly.vertices), [&](const Eigen::AlignedBox2d& c) {
      const Eigen::Vector2d square[4] = {c.min(), {c.max().x(), c.min().y()}, c.max(), {c.min().x(), c.max().y()}};
      return world::polygons_overlap(square, poly.vertices);
    });
  }
  for (const world::Circle& circle : change.shapes.circles) {
    const Eigen::Vector2d reach = Eigen::Vector2d::Constant(circle.radius);
    for_cells_under(Eigen::AlignedBox2d(circle.center - reach, circle.center + reach), [&](const Eigen::AlignedBox2d& c) {
      return c.squaredExteriorDistance(circle.center) < circle.radius * circle.radius;
    });
  }
  return std::make_shared<const GridNavWorld>(std::move(map));
}

}  // namespace amp::nav
