#include "amp/world/distance_transform.hpp"

#include <algorithm>
#include <string>

#include "amp/core/error.hpp"
#include "amp/world/occupancy_grid.hpp"

namespace amp::world {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
}  // namespace

DistanceTransform::DistanceTransform(const OccupancyGrid& grid) {
  std::vector<std::uint8_t> site(grid.cell_count());
  for (std::size_t i = 0; i < site.size(); ++i) site[i] = grid.cells()[i] != CellState::kFree ? 1 : 0;
  compute(grid.width(), grid.height(), site);
}

void DistanceTransform::compute(int width, int height, const std::vector<std::uint8_t>& site) {
  const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  if (width < 1 || height < 1 || site.size() != n) {
    throw ParameterError("distance transform: raster of " + std::to_string(site.size()) + " cells is not " +
                         std::to_string(width) + "x" + std::to_string(height));
  }
  width_ = width;
  height_ = height;
  sq_distance_.resize(n);
  nearest_.resize(n);
  column_site_.resize(n);
  f_.resize(static_cast<std::size_t>(width));
  v_.resize(static_cast<std::size_t>(width));
  z_.resize(static_cast<std::size_t>(width) + 1);
  column_pass(site);
  row_pass();
}

// 1-D transform of every column of the indicator function (0 at sites, infinity elsewhere): the
// nearest site in a column is the nearer of the last site below and the next site above. Swept row
// by row (all columns at once) so that memory is read in order.
void DistanceTransform::column_pass(const std::vector<std::uint8_t>& site) {
  const std::size_t w = static_cast<std::size_t>(width_);
  std::int32_t* last = v_.data();  // per column: the latest site row seen by the sweep
  std::fill(v_.begin(), v_.end(), -1);
  for (int y = 0; y < height_; ++y) {
    const std::size_t row = static_cast<std::size_t>(y) * w;
    for (std::size_t x = 0; x < w; ++x) {
      if (site[row + x]) last[x] = y;
      column_site_[row + x] = last[x];
    }
  }
  std::fill(v_.begin(), v_.end(), -1);
  for (int y = height_ - 1; y >= 0; --y) {
    const std::size_t row = static_cast<std::size_t>(y) * w;
    for (std::size_t x = 0; x < w; ++x) {
      if (site[row + x]) last[x] = y;
      const std::int32_t below = column_site_[row + x];
      if (last[x] >= 0 && (below < 0 || last[x] - y < y - below)) column_site_[row + x] = last[x];
    }
  }
}

// Lower envelope of the parabolas (x - q)^2 + f(q) along every row (FH Algorithm 1); columns without
// a site (f = infinity) contribute no parabola.
void DistanceTransform::row_pass() {
  const std::size_t w = static_cast<std::size_t>(width_);
  for (int y = 0; y < height_; ++y) {
    const std::size_t row = static_cast<std::size_t>(y) * w;
    for (int x = 0; x < width_; ++x) {
      const int sy = column_site_[row + static_cast<std::size_t>(x)];
      f_[static_cast<std::size_t>(x)] = sy < 0 ? kInf : static_cast<double>(sy - y) * (sy - y);
    }
    int k = -1;  // index of the rightmost parabola in the envelope
    for (int q = 0; q < width_; ++q) {
      const double fq = f_[static_cast<std::size_t>(q)];
      if (fq == kInf) continue;
      if (k < 0) {
        k = 0;
        v_[0] = q;
        z_[0] = -kInf;
        z_[1] = kInf;
        continue;
      }
      double s = 0.0;
      for (;;) {  // lines 5-9: pop parabolas hidden by q; z[0] = -inf ends the loop
        const int p = v_[static_cast<std::size_t>(k)];
        s = ((fq + double(q) * q) - (f_[static_cast<std::size_t>(p)] + double(p) * p)) / (2.0 * (q - p));
        if (s > z_[static_cast<std::size_t>(k)]) break;
        --k;
      }
      ++k;  // lines 10-13
      v_[static_cast<std::size_t>(k)] = q;
      z_[static_cast<std::size_t>(k)] = s;
      z_[static_cast<std::size_t>(k) + 1] = kInf;
    }
    if (k < 0) {  // no site in any column: every cell is infinitely far
      for (int x = 0; x < width_; ++x) {
        sq_distance_[row + static_cast<std::size_t>(x)] = kInf;
        nearest_[row + static_cast<std::size_t>(x)] = -1;
      }
      continue;
    }
    k = 0;
    for (int x = 0; x < width_; ++x) {  // lines 14-17
      while (z_[static_cast<std::size_t>(k) + 1] < x) ++k;
      const int p = v_[static_cast<std::size_t>(k)];
      const double dx = x - p;
      sq_distance_[row + static_cast<std::size_t>(x)] = dx * dx + f_[static_cast<std::size_t>(p)];
      const int sy = column_site_[row + static_cast<std::size_t>(p)];
      nearest_[row + static_cast<std::size_t>(x)] = static_cast<std::int32_t>(static_cast<std::size_t>(sy) * w + p);
    }
  }
}

}  // namespace amp::world
