#pragma once
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace amp::world {

class OccupancyGrid;

// Exact Euclidean distance transform of a binary raster, in linear time: Felzenszwalb and
// Huttenlocher, "Distance Transforms of Sampled Functions", Theory of Computing 8(19), 2012. A 1-D
// pass down every column, then the lower envelope of parabolas (Algorithm 1, "DT(f)") along every
// row. For every cell it gives the squared distance, in cells, from its centre to the nearest site
// centre and that site's index. Distances between cell centres; the grid checkers turn them into
// exact distances to obstacle squares.
class DistanceTransform {
 public:
  static constexpr double kNoSite = std::numeric_limits<double>::infinity();

  DistanceTransform() = default;
  // Sites: cells with site[i] != 0, row-major width x height.
  DistanceTransform(int width, int height, const std::vector<std::uint8_t>& site) { compute(width, height, site); }
  // Sites: the grid's blocked (occupied or unknown) cells.
  explicit DistanceTransform(const OccupancyGrid& grid);

  // Recomputes in place; reuses its buffers when the size is unchanged.
  void compute(int width, int height, const std::vector<std::uint8_t>& site);

  int width() const { return width_; }
  int height() const { return height_; }
  // Squared distance in cells from cell i's centre to the nearest site's centre; kNoSite if none.
  double squared_distance(std::size_t i) const { return sq_distance_[i]; }
  // Row-major index of the nearest site, -1 if there is none.
  std::int32_t nearest(std::size_t i) const { return nearest_[i]; }
  const std::vector<double>& squared_distances() const { return sq_distance_; }

 private:
  void column_pass(const std::vector<std::uint8_t>& site);
  void row_pass();

  int width_ = 0;
  int height_ = 0;
  std::vector<double> sq_distance_;
  std::vector<std::int32_t> nearest_;
  // Column pass output: nearest site row per cell (-1 none); then scratch of the 1-D envelope.
  std::vector<std::int32_t> column_site_;
  std::vector<double> f_;
  std::vector<double> z_;
  std::vector<std::int32_t> v_;
};

}  // namespace amp::world
