#include <algorithm>
#include <cmath>

#include "amp/world/planar_world.hpp"
#include "amp/world/polygon_geometry.hpp"

namespace amp::world {

namespace {
// Cell side = kCellScale * sqrt(area per item): about one edge per cell on average, which keeps a
// robot's cell range short while most cells hold 0-2 edges (tuned on benchmarks/planar_checker_bench).
constexpr double kCellScale = 1.0;
constexpr int kMaxCellsPerAxis = 1024;
constexpr long kMaxCells = 1L << 20;
// Reference point of a cell, as a fraction of the cell: off-centre by odd amounts so that it does not
// fall on the axis-aligned or diagonal obstacle edges that hand-made worlds are full of.
constexpr double kRefX = 0.5137294;
constexpr double kRefY = 0.4862917;
// Cells are grown by this fraction of their side when assigning edges, so that rounding never drops
// an edge that touches a cell border.
constexpr double kCellSlack = 1e-9;

// Closed segment ab meets closed box (ab's own box is known to overlap it).
bool segment_meets_box(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::AlignedBox2d& box) {
  const Eigen::Vector2d corners[4] = {box.min(), {box.max().x(), box.min().y()}, box.max(), {box.min().x(), box.max().y()}};
  bool pos = false, neg = false;
  for (const Eigen::Vector2d& c : corners) {
    const double o = orient2d(a, b, c);
    pos = pos || o >= 0.0;
    neg = neg || o <= 0.0;
  }
  return pos && neg;
}

// Builds compressed rows from a visitor called twice: once to count, once to fill.
template <class Visit>
void build_rows(int cells, int items, Visit visit, std::vector<int>& start, std::vector<int>& ids) {
  start.assign(cells + 1, 0);
  for (int i = 0; i < items; ++i) visit(i, [&](int cell) { ++start[cell + 1]; });
  for (int c = 0; c < cells; ++c) start[c + 1] += start[c];
  ids.resize(start[cells]);
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (int i = 0; i < items; ++i) visit(i, [&](int cell) { ids[fill[cell]++] = i; });
}
}  // namespace

PlanarGrid::PlanarGrid(const std::vector<PlanarEdge>& edges, const Shapes2d& obstacles,
                       const std::vector<Eigen::AlignedBox2d>& polygon_boxes,
                       const std::vector<Eigen::AlignedBox2d>& circle_boxes) {
  const int items = static_cast<int>(edges.size() + circle_boxes.size());
  if (items == 0) return;
  for (const auto& b : polygon_boxes) extent_.extend(b);
  for (const auto& e : edges) extent_.extend(e.box);  // segment walls belong to no polygon
  for (const auto& b : circle_boxes) extent_.extend(b);
  const Eigen::Vector2d size = extent_.sizes();
  const double pad = 1e-9 * std::max(size.x(), size.y());
  extent_.min().array() -= pad;
  extent_.max().array() += pad;
  const Eigen::Vector2d padded = extent_.sizes();
  cell_ = kCellScale * std::sqrt(padded.x() * padded.y() / items);
  // Thin worlds (a single wall) have near-zero area: fall back to the long side per item.
  cell_ = std::max(cell_, std::max(padded.x(), padded.y()) / kMaxCellsPerAxis);
  for (;;) {
    nx_ = std::max(1, static_cast<int>(std::ceil(padded.x() / cell_)));
    ny_ = std::max(1, static_cast<int>(std::ceil(padded.y() / cell_)));
    if (static_cast<long>(nx_) * ny_ <= kMaxCells) break;
    cell_ *= 1.25;
  }
  inv_cell_ = 1.0 / cell_;
  const int cells = nx_ * ny_;
  auto cell_box = [&](int ix, int iy) {
    const Eigen::Vector2d lo = extent_.min() + cell_ * Eigen::Vector2d(ix, iy);
    const Eigen::Vector2d slack = Eigen::Vector2d::Constant(kCellSlack * cell_);
    return Eigen::AlignedBox2d(lo - slack, lo + Eigen::Vector2d::Constant(cell_) + slack);
  };

  build_rows(
      cells, static_cast<int>(edges.size()),
      [&](int e, auto emit) {
        int x0, y0, x1, y1;
        if (!cell_range(edges[e].box, x0, y0, x1, y1)) return;
        for (int iy = y0; iy <= y1; ++iy) {
          for (int ix = x0; ix <= x1; ++ix) {
            if (segment_meets_box(edges[e].a, edges[e].b, cell_box(ix, iy))) emit(cell_index(ix, iy));
          }
        }
      },
      edge_start_, edge_ids_);

  build_rows(
      cells, static_cast<int>(circle_boxes.size()),
      [&](int k, auto emit) {
        int x0, y0, x1, y1;
        if (!cell_range(circle_boxes[k], x0, y0, x1, y1)) return;
        const Circle& c = obstacles.circles[k];
        for (int iy = y0; iy <= y1; ++iy) {
          for (int ix = x0; ix <= x1; ++ix) {
            if (cell_box(ix, iy).squaredExteriorDistance(c.center) <= c.radius * c.radius) emit(cell_index(ix, iy));
          }
        }
      },
      circle_start_, circle_ids_);

  build_rows(
      cells, static_cast<int>(polygon_boxes.size()),
      [&](int p, auto emit) {
        int x0, y0, x1, y1;
        if (!cell_range(polygon_boxes[p], x0, y0, x1, y1)) return;
        const std::vector<Eigen::Vector2d>& v = obstacles.polygons[p].vertices;
        for (int iy = y0; iy <= y1; ++iy) {
          for (int ix = x0; ix <= x1; ++ix) {
            const Eigen::Vector2d r = reference_point(cell_index(ix, iy));
            if (polygon_boxes[p].contains(r) && point_in_polygon(r, v)) emit(cell_index(ix, iy));
          }
        }
      },
      inside_start_, inside_ids_);

  for (int c = 0; c < cells; ++c) {
    max_parity_items_ = std::max(max_parity_items_, static_cast<int>(edges_in(c).size() + polygons_around(c).size()));
  }
}

Eigen::Vector2d PlanarGrid::reference_point(int cell) const {
  const int ix = cell % nx_;
  const int iy = cell / nx_;
  return extent_.min() + cell_ * Eigen::Vector2d(ix + kRefX, iy + kRefY);
}

}  // namespace amp::world
