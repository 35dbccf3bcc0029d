#pragma once
#include <span>
#include <string_view>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "amp/world/shapes2d.hpp"

namespace amp::world {

// One obstacle polygon edge, stored flat for the broad phase.
struct PlanarEdge {
  Eigen::Vector2d a;
  Eigen::Vector2d b;
  Eigen::AlignedBox2d box;
  int polygon = 0;  // index into obstacles().polygons
};

// Uniform grid over obstacle edges and circles (compressed rows, one allocation each). Each cell
// also lists the polygons that contain its reference point, so "is p inside an obstacle?" costs
// only the edges of p's cell: parity(p) = parity(reference) xor crossings of the segment
// reference -> p, and that segment never leaves the cell.
class PlanarGrid {
 public:
  PlanarGrid() = default;
  PlanarGrid(const std::vector<PlanarEdge>& edges, const Shapes2d& obstacles,
             const std::vector<Eigen::AlignedBox2d>& polygon_boxes, const std::vector<Eigen::AlignedBox2d>& circle_boxes);

  bool empty() const { return nx_ == 0; }
  int nx() const { return nx_; }
  int ny() const { return ny_; }
  double cell_size() const { return cell_; }
  // The box the cells tile (the obstacles' extent, slightly padded); empty when there are none.
  const Eigen::AlignedBox2d& extent() const { return extent_; }
  // Inclusive cell range overlapping `box`; false when `box` misses the grid.
  bool cell_range(const Eigen::AlignedBox2d& box, int& x0, int& y0, int& x1, int& y1) const {
    if (empty() || !box.intersects(extent_)) return false;
    x0 = clamp_cell((box.min().x() - extent_.min().x()) * inv_cell_, nx_);
    x1 = clamp_cell((box.max().x() - extent_.min().x()) * inv_cell_, nx_);
    y0 = clamp_cell((box.min().y() - extent_.min().y()) * inv_cell_, ny_);
    y1 = clamp_cell((box.max().y() - extent_.min().y()) * inv_cell_, ny_);
    return true;
  }
  // Cell holding p, or -1 outside the grid (hence outside every obstacle).
  int cell_of(const Eigen::Vector2d& p) const {
    if (empty() || !extent_.contains(p)) return -1;
    return cell_index(clamp_cell((p.x() - extent_.min().x()) * inv_cell_, nx_),
                      clamp_cell((p.y() - extent_.min().y()) * inv_cell_, ny_));
  }
  int cell_index(int ix, int iy) const { return iy * nx_ + ix; }
  std::span<const int> edges_in(int cell) const { return row(edge_start_, edge_ids_, cell); }
  std::span<const int> circles_in(int cell) const { return row(circle_start_, circle_ids_, cell); }
  // Polygons that contain the reference point of `cell`.
  std::span<const int> polygons_around(int cell) const { return row(inside_start_, inside_ids_, cell); }
  Eigen::Vector2d reference_point(int cell) const;
  // Largest edges_in(c).size() + polygons_around(c).size(): scratch size for the parity test.
  int max_parity_items() const { return max_parity_items_; }

 private:
  // Clamped in floating point first: a far-away box must not overflow the int conversion.
  static int clamp_cell(double v, int n) { return v <= 0.0 ? 0 : (v >= n ? n - 1 : static_cast<int>(v)); }
  static std::span<const int> row(const std::vector<int>& start, const std::vector<int>& ids, int cell) {
    return {ids.data() + start[cell], static_cast<std::size_t>(start[cell + 1] - start[cell])};
  }

  Eigen::AlignedBox2d extent_;
  double cell_ = 0.0, inv_cell_ = 0.0;
  int nx_ = 0, ny_ = 0;
  std::vector<int> edge_start_, edge_ids_, circle_start_, circle_ids_, inside_start_, inside_ids_;
  int max_parity_items_ = 0;
};

// Throws ParameterError unless every polygon has >= 3 finite vertices, non-zero area and no
// self-intersection, and every circle a finite centre and radius > min_radius (obstacles: 0;
// robot bodies may use -1 to allow a point, radius 0). `what` starts the message ("obstacle").
void validate_shapes(const Shapes2d& shapes, std::string_view what, double min_radius = 0.0);

// An immutable 2-D world: polygon (convex or not) and circle obstacles inside workspace bounds,
// with a uniform-grid broad phase so that a check costs the obstacles near the robot only.
class PlanarWorld {
 public:
  // Throws ParameterError for invalid shapes (see validate_shapes) or empty/non-finite bounds.
  PlanarWorld(Shapes2d obstacles, Eigen::AlignedBox2d bounds);

  const Shapes2d& obstacles() const { return obstacles_; }
  const Eigen::AlignedBox2d& bounds() const { return bounds_; }

  const std::vector<PlanarEdge>& edges() const { return edges_; }
  // edges()[first_segment_edge() ..] are the segment walls (PlanarEdge::polygon = -1).
  int first_segment_edge() const { return first_segment_edge_; }
  const std::vector<Eigen::AlignedBox2d>& polygon_boxes() const { return polygon_boxes_; }
  const std::vector<Eigen::AlignedBox2d>& circle_boxes() const { return circle_boxes_; }
  const PlanarGrid& grid() const { return grid_; }

  // Whether p lies strictly inside some obstacle polygon (boundary points may go either way).
  // `scratch` must have capacity >= grid().max_parity_items(); it is not reallocated.
  bool point_in_obstacle_polygon(const Eigen::Vector2d& p, std::vector<int>& scratch) const;

 private:
  Shapes2d obstacles_;
  Eigen::AlignedBox2d bounds_;
  std::vector<PlanarEdge> edges_;
  int first_segment_edge_ = 0;
  std::vector<Eigen::AlignedBox2d> polygon_boxes_;
  std::vector<Eigen::AlignedBox2d> circle_boxes_;
  PlanarGrid grid_;
};

}  // namespace amp::world
