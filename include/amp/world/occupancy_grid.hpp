#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace amp::world {

// What a map says about one cell. Unknown cells count as obstacles for planning (a robot must not
// drive where the map has never seen), see OccupancyGrid::blocked().
enum class CellState : std::uint8_t { kFree = 0, kOccupied = 1, kUnknown = 2 };

// A 2-D occupancy grid as ROS map_server and MovingAI describe one: width x height square cells of
// side resolution (m/cell), cell (0, 0) at the lower-left corner whose outer corner sits at the
// origin; cells stored row-major with row 0 = lowest y. Map rotation (origin yaw) is not supported:
// the loaders reject yaw != 0 rather than silently misplacing obstacles.
class OccupancyGrid {
 public:
  // Throws ParameterError for width/height < 1 or resolution <= 0. All cells start free.
  OccupancyGrid(int width, int height, double resolution, Eigen::Vector2d origin = Eigen::Vector2d::Zero());

  int width() const { return width_; }
  int height() const { return height_; }
  double resolution() const { return resolution_; }
  const Eigen::Vector2d& origin() const { return origin_; }
  std::size_t cell_count() const { return cells_.size(); }

  bool contains_cell(int cx, int cy) const { return cx >= 0 && cy >= 0 && cx < width_ && cy < height_; }
  std::size_t index(int cx, int cy) const {
    return static_cast<std::size_t>(cy) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(cx);
  }

  CellState state(int cx, int cy) const { return cells_[index(cx, cy)]; }
  // Also resets the cell's value to map_server's canonical 0 / 100 / -1.
  void set_state(int cx, int cy, CellState s) {
    const std::size_t i = index(cx, cy);
    cells_[i] = s;
    values_[i] = s == CellState::kFree ? 0 : s == CellState::kOccupied ? 100 : -1;
  }
  // Occupied or unknown: an obstacle for planning.
  bool blocked(int cx, int cy) const { return cells_[index(cx, cy)] != CellState::kFree; }
  const std::vector<CellState>& cells() const { return cells_; }

  // The value map_server would publish in nav_msgs/OccupancyGrid.data (-1 unknown, 0..100, or the
  // raw pixel in `raw` mode); defaults to 0/100/-1 from the state when a loader sets none.
  std::int8_t value(int cx, int cy) const { return values_[index(cx, cy)]; }
  void set_value(int cx, int cy, std::int8_t v) { values_[index(cx, cy)] = v; }

  // The cell containing world point p (floor of the cell coordinates; may lie outside the grid).
  Eigen::Vector2i world_to_cell(const Eigen::Vector2d& p) const;
  // Continuous cell coordinates of p: cell (cx, cy) spans [cx, cx + 1) x [cy, cy + 1).
  Eigen::Vector2d world_to_grid(const Eigen::Vector2d& p) const { return (p - origin_) / resolution_; }
  Eigen::Vector2d cell_center(int cx, int cy) const;
  // The square a cell covers, in world coordinates.
  Eigen::AlignedBox2d cell_box(int cx, int cy) const;
  // The whole map's rectangle in world coordinates.
  Eigen::AlignedBox2d extent() const;

  std::size_t count(CellState s) const;

 private:
  int width_;
  int height_;
  double resolution_;
  Eigen::Vector2d origin_;
  std::vector<CellState> cells_;
  std::vector<std::int8_t> values_;
};

}  // namespace amp::world
