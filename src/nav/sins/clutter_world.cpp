#include "amp/nav/sins/clutter_world.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "amp/core/error.hpp"
#include "amp/core/number_text.hpp"
#include "amp/core/rng.hpp"
#include "amp/nav/polygon_nav_world.hpp"
#include "amp/nav/reference_grid.hpp"

namespace amp::nav {

namespace {

constexpr double kEndZone = 0.15;       // start and goal lie in this share of each end of the long side
constexpr int kMaxFutileDraws = 1000;   // draws in a row that cover nothing new: the target is out of reach
constexpr double kMaxRasterCells = double(1 << 28);  // as rasterize_free_space: memory, not accuracy
// The cover raster is finer than the reference grid so that the achieved clutter is measured more
// closely than the robot's free space is resolved.
constexpr double kCoverCellsPerReferenceCell = 2.0;

// The shortest text that reads back as v ("0.9", not "0.900000").
void require(bool ok, const std::string& what) {
  if (!ok) throw ParameterError("clutter world: " + what);
}

// Which cells of a raster tiling the box exactly have their centre in some circle. Cells are about
// `cell` on a side: n = round(side / cell) per side, so the box is never over- or under-counted by a
// partial row or column.
class CoverRaster {
 public:
  CoverRaster(double width, double height, double cell)
      : nx_(cells_along(width, cell)), ny_(cells_along(height, cell)), dx_(width / nx_), dy_(height / ny_) {
    if (static_cast<double>(nx_) * static_cast<double>(ny_) > kMaxRasterCells) {
      throw ParameterError("clutter raster: cell " + core::number_text(cell) + " makes more than 2^28 cells");
    }
    covered_.assign(static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_), 0);
  }

  // Covers the cells whose centre lies in c (row by row, over the chord's span); returns how many
  // were not covered before.
  std::int64_t add(const world::Circle& c) {
    const double r = c.radius;
    std::int64_t added = 0;
    const int j0 = std::max(0, clamp_index(std::ceil((c.center.y() - r) / dy_ - 0.5), ny_));
    const int j1 = std::min(ny_ - 1, clamp_index(std::floor((c.center.y() + r) / dy_ - 0.5), ny_));
    for (int j = j0; j <= j1; ++j) {
      const double off = (j + 0.5) * dy_ - c.center.y();
      const double h2 = r * r - off * off;
      if (h2 < 0.0) continue;
      const double h = std::sqrt(h2);
      const int i0 = std::max(0, clamp_index(std::ceil((c.center.x() - h) / dx_ - 0.5), nx_));
      const int i1 = std::min(nx_ - 1, clamp_index(std::floor((c.center.x() + h) / dx_ - 0.5), nx_));
      std::uint8_t* row = covered_.data() + static_cast<std::size_t>(j) * static_cast<std::size_t>(nx_);
      for (int i = i0; i <= i1; ++i) {
        added += row[i] == 0;
        row[i] = 1;
      }
    }
    covered_count_ += added;
    return added;
  }

  std::int64_t covered() const { return covered_count_; }
  double total() const { return static_cast<double>(covered_.size()); }
  double fraction() const { return static_cast<double>(covered_count_) / total(); }

 private:
  // A whole-valued v clamped to [-1, n] in floating point first, so a far circle cannot overflow the
  // int; the callers clamp further to the rows or columns that exist.
  static int clamp_index(double v, int n) { return v <= -1.0 ? -1 : (v >= n ? n : static_cast<int>(v)); }
  static int cells_along(double side, double cell) {
    const double n = std::max(1.0, std::round(side / cell));
    return n > kMaxRasterCells ? std::numeric_limits<int>::max() : static_cast<int>(n);
  }

  int nx_, ny_;
  double dx_, dy_;
  std::vector<std::uint8_t> covered_;
  std::int64_t covered_count_ = 0;
};

double cover_cell(const ClutterWorldSettings& s) { return s.reference_cell / kCoverCellsPerReferenceCell; }

// The world around the circles and its grid-shortest start-goal length (+infinity when cut off).
ClutterWorld finish(std::vector<world::Circle> circles, const Eigen::Vector2d& start, const Eigen::Vector2d& goal,
                    double clutter, const ClutterWorldSettings& s) {
  ClutterWorld out;
  const Eigen::AlignedBox2d box(Eigen::Vector2d::Zero(), Eigen::Vector2d(s.width, s.height));
  out.world = std::make_shared<const PolygonNavWorld>(world::Shapes2d{{}, circles}, box);
  ReferenceGrid grid(*out.world, s.robot_radius, s.reference_cell);
  out.optimal_length = grid.shortest_length(start, goal);
  out.circles = std::move(circles);
  out.start = start;
  out.goal = goal;
  out.clutter = clutter;
  return out;
}

// Whether start and goal may be connected for the robot disc: a flood fill over the reference grid's
// cells (laid out as rasterize_free_space does) made more permissive than the ReferenceGrid's: the box
// blocks nothing, a cell is blocked only when its centre is inside a circle grown by the robot radius
// by more than rounding, and diagonal steps may cut corners. Its free cells and steps include the
// ReferenceGrid's, so "no" here is "no" there: a cut-off world is rejected at a fraction of the cost
// of rasterising every cell against the world (the rejections come at high clutter, in numbers).
bool may_connect(const std::vector<world::Circle>& circles, const Eigen::Vector2d& start, const Eigen::Vector2d& goal,
                 const ClutterWorldSettings& s) {
  constexpr double kWholeCellSlack = 1e-9;  // as rasterize_free_space: the same columns and rows
  constexpr double kRounding = 1e-9;        // relative: blocked only when clearly inside
  const double cell = s.reference_cell;
  const int nx = static_cast<int>(std::max(1.0, std::ceil(s.width / cell - kWholeCellSlack)));
  const int ny = static_cast<int>(std::max(1.0, std::ceil(s.height / cell - kWholeCellSlack)));
  std::vector<std::uint8_t> state(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny), 1);  // 1 free, 2 seen
  for (const world::Circle& c : circles) {
    const double reach = c.radius + s.robot_radius;
    const double reach2 = reach * reach * (1.0 - kRounding);
    const int x0 = std::max(0, static_cast<int>(std::floor((c.center.x() - reach) / cell)));
    const int x1 = std::min(nx - 1, static_cast<int>(std::floor((c.center.x() + reach) / cell)));
    const int y0 = std::max(0, static_cast<int>(std::floor((c.center.y() - reach) / cell)));
    const int y1 = std::min(ny - 1, static_cast<int>(std::floor((c.center.y() + reach) / cell)));
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const Eigen::Vector2d centre = cell * Eigen::Vector2d(x + 0.5, y + 0.5);
        if ((centre - c.center).squaredNorm() < reach2) state[static_cast<std::size_t>(y * nx + x)] = 0;
      }
    }
  }
  // ReferenceGrid::cell_near takes the point's cell or one of its 8 neighbours.
  const auto around = [&](const Eigen::Vector2d& p, auto&& visit) {
    const int px = static_cast<int>(std::floor(p.x() / cell)), py = static_cast<int>(std::floor(p.y() / cell));
    for (int y = std::max(0, py - 1); y <= std::min(ny - 1, py + 1); ++y) {
      for (int x = std::max(0, px - 1); x <= std::min(nx - 1, px + 1); ++x) visit(y * nx + x);
    }
  };
  std::vector<int> queue;
  around(start, [&](int i) {
    if (state[static_cast<std::size_t>(i)] == 1) state[static_cast<std::size_t>(i)] = 2, queue.push_back(i);
  });
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const int x = queue[head] % nx, y = queue[head] / nx;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        if (x + dx < 0 || y + dy < 0 || x + dx >= nx || y + dy >= ny) continue;
        const int n = (y + dy) * nx + x + dx;
        if (state[static_cast<std::size_t>(n)] == 1) state[static_cast<std::size_t>(n)] = 2, queue.push_back(n);
      }
    }
  }
  bool reached = false;
  around(goal, [&](int i) { reached = reached || state[static_cast<std::size_t>(i)] == 2; });
  return reached;
}

// A point `along` the long side and `across` it, in box coordinates.
Eigen::Vector2d place(const ClutterWorldSettings& s, double along, double across) {
  return s.width >= s.height ? Eigen::Vector2d(along, across) : Eigen::Vector2d(across, along);
}

}  // namespace

void ClutterWorldSettings::validate() const {
  require(std::isfinite(width) && width > 0.0, "width must be > 0, got " + core::number_text(width));
  require(std::isfinite(height) && height > 0.0, "height must be > 0, got " + core::number_text(height));
  require(clutter > 0.0 && clutter < 1.0, "clutter must be in (0, 1), got " + core::number_text(clutter));
  require(std::isfinite(min_radius) && min_radius > 0.0, "min_radius must be > 0, got " + core::number_text(min_radius));
  require(std::isfinite(max_radius) && max_radius >= min_radius,
          "max_radius must be >= min_radius " + core::number_text(min_radius) + ", got " + core::number_text(max_radius));
  require(std::isfinite(robot_radius) && robot_radius > 0.0, "robot_radius must be > 0, got " + core::number_text(robot_radius));
  require(std::isfinite(start_goal_margin) && start_goal_margin >= 0.0,
          "start_goal_margin must be >= 0, got " + core::number_text(start_goal_margin));
  require(std::isfinite(reference_cell) && reference_cell > 0.0,
          "reference_cell must be > 0, got " + core::number_text(reference_cell));
  require(max_tries >= 1, "max_tries must be >= 1, got " + std::to_string(max_tries));
  const double room = 2.0 * clearance();
  require(width > room && height > room, "a " + core::number_text(width) + " x " + core::number_text(height) +
                                             " box has no room for the start and goal (each side must exceed 2 * "
                                             "(robot_radius + start_goal_margin) = " + core::number_text(room) + ")");
  const double cells = (width / cover_cell(*this)) * (height / cover_cell(*this));
  require(cells <= kMaxRasterCells, "reference_cell " + core::number_text(reference_cell) + " makes more than 2^28 raster cells");
}

double clutter_fraction(const std::vector<world::Circle>& circles, double width, double height, double cell) {
  if (!(width > 0.0 && height > 0.0)) throw ParameterError("clutter raster: box size must be > 0");
  if (!(cell > 0.0)) throw ParameterError("clutter raster: cell must be > 0, got " + core::number_text(cell));
  CoverRaster raster(width, height, cell);
  for (const world::Circle& c : circles) {
    if (!c.center.allFinite() || !(std::isfinite(c.radius) && c.radius >= 0.0)) {
      throw ParameterError("clutter raster: circles need a finite centre and radius >= 0");
    }
    raster.add(c);
  }
  return raster.fraction();
}

ClutterWorld assemble_clutter_world(std::vector<world::Circle> circles, const Eigen::Vector2d& start,
                                    const Eigen::Vector2d& goal, const ClutterWorldSettings& settings) {
  settings.validate();
  const double clutter = clutter_fraction(circles, settings.width, settings.height, cover_cell(settings));
  return finish(std::move(circles), start, goal, clutter, settings);
}

ClutterWorld make_clutter_world(const ClutterWorldSettings& s, core::Rng& rng) {
  s.validate();
  const double clear = s.clearance();
  const double length = std::max(s.width, s.height), across = std::min(s.width, s.height);
  const double zone = std::max(clear, kEndZone * length);
  const double target = s.clutter;
  int cut_off = 0, not_reached = 0;
  double best_reached = 0.0;
  for (int attempt = 0; attempt < s.max_tries; ++attempt) {
    const double sa = rng.uniform(clear, zone), sc = rng.uniform(clear, across - clear);
    const double ga = rng.uniform(length - zone, length - clear), gc = rng.uniform(clear, across - clear);
    const Eigen::Vector2d start = place(s, sa, sc), goal = place(s, ga, gc);

    CoverRaster raster(s.width, s.height, cover_cell(s));
    std::vector<world::Circle> circles;
    int futile = 0;
    while (raster.fraction() < target && futile < kMaxFutileDraws) {
      world::Circle c;
      c.center = Eigen::Vector2d(rng.uniform(0.0, s.width), rng.uniform(0.0, s.height));
      c.radius = rng.uniform(s.min_radius, s.max_radius);
      const double keep = c.radius + clear;  // the start and goal discs stay `margin` from the circle
      if ((c.center - start).squaredNorm() < keep * keep || (c.center - goal).squaredNorm() < keep * keep) {
        ++futile;
        continue;
      }
      futile = raster.add(c) > 0 ? 0 : futile + 1;
      circles.push_back(c);
    }
    if (raster.fraction() < target) {
      ++not_reached;
      best_reached = std::max(best_reached, raster.fraction());
      continue;
    }
    if (may_connect(circles, start, goal, s)) {
      ClutterWorld w = finish(std::move(circles), start, goal, raster.fraction(), s);
      if (std::isfinite(w.optimal_length)) {
        w.rejected = attempt;
        return w;
      }
    }
    ++cut_off;
  }
  if (cut_off == 0) {
    throw ParameterError("clutter " + core::number_text(target) + ": not reached in " + std::to_string(s.max_tries) +
                         " tries with circles kept " + core::number_text(clear) + " m from start and goal (at most " +
                         core::number_text(best_reached) + " covered)");
  }
  throw ParameterError("clutter " + core::number_text(target) + ": no world with a free path in " + std::to_string(s.max_tries) +
                       " tries");
}

ClutterWorldSequence::ClutterWorldSequence(std::uint64_t seed, ClutterWorldSettings settings)
    : seed_(seed), settings_(settings) {
  settings_.validate();
}

ClutterWorld ClutterWorldSequence::at(int i) const {
  if (i < 0) throw ParameterError("clutter world sequence: index must be >= 0, got " + std::to_string(i));
  core::Rng rng(core::derive_seed(seed_, static_cast<std::uint64_t>(i)));
  return make_clutter_world(settings_, rng);
}

ClutterWorld ClutterWorldSequence::next() {
  ClutterWorld w = at(index_);
  rejected_total_ += w.rejected;
  ++index_;
  return w;
}

void ClutterWorldSequence::seek(int i) {
  if (i < 0) throw ParameterError("clutter world sequence: index must be >= 0, got " + std::to_string(i));
  index_ = i;
}

void ClutterWorldSequence::set_clutter(double clutter) {
  ClutterWorldSettings changed = settings_;
  changed.clutter = clutter;
  changed.validate();
  settings_ = changed;
}

}  // namespace amp::nav
