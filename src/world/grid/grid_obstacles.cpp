#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "amp/world/grid_environment.hpp"

namespace amp::world {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Cell-unit slack on the distance-transform bound, so rounding never turns "maybe" into "free".
constexpr double kBoundSlack = 1e-9;

double sq(double x) { return x * x; }

// Closest point of a closed box to p.
Eigen::Vector2d clamp_to_box(const Eigen::Vector2d& p, const Eigen::AlignedBox2d& b) {
  return p.cwiseMax(b.min()).cwiseMin(b.max());
}

// Squared distance from p to segment [a, b] and the closest point.
double sq_point_segment(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                        Eigen::Vector2d& closest) {
  const Eigen::Vector2d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  closest = a + t * ab;
  return (p - closest).squaredNorm();
}

// Closed segment [a, b] meets closed box (Liang-Barsky clipping).
bool segment_meets_box(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::AlignedBox2d& box) {
  double t0 = 0.0, t1 = 1.0;
  for (int k = 0; k < 2; ++k) {
    const double d = b[k] - a[k];
    if (d == 0.0) {
      if (a[k] < box.min()[k] || a[k] > box.max()[k]) return false;
      continue;
    }
    double te = (box.min()[k] - a[k]) / d;
    double tx = (box.max()[k] - a[k]) / d;
    if (te > tx) std::swap(te, tx);
    t0 = std::max(t0, te);
    t1 = std::min(t1, tx);
    if (t0 > t1) return false;
  }
  return true;
}

// Even-odd rule; any orientation.
bool point_in_polygon(const Eigen::Vector2d& p, const Eigen::Vector2d* v, int n) {
  bool inside = false;
  for (int i = 0, j = n - 1; i < n; j = i++) {
    if ((v[i].y() > p.y()) != (v[j].y() > p.y()) &&
        p.x() < (v[j].x() - v[i].x()) * (p.y() - v[i].y()) / (v[j].y() - v[i].y()) + v[i].x()) {
      inside = !inside;
    }
  }
  return inside;
}

// Closed polygon region meets closed box: an edge touches the box, or else the box lies wholly
// inside or outside the polygon and its centre tells which.
bool polygon_meets_box(const Eigen::Vector2d* v, int n, const Eigen::AlignedBox2d& box) {
  for (int i = 0, j = n - 1; i < n; j = i++) {
    if (segment_meets_box(v[j], v[i], box)) return true;
  }
  return point_in_polygon(box.center(), v, n);
}

Eigen::AlignedBox2d bounding_box(const Eigen::Vector2d* v, int n) {
  Eigen::AlignedBox2d b;
  for (int i = 0; i < n; ++i) b.extend(v[i]);
  return b;
}

}  // namespace

GridObstacles::GridObstacles(std::shared_ptr<const OccupancyGrid> grid)
    : grid_(std::move(grid)), edt_(*grid_), extent_(grid_->extent()) {
  const int w = grid_->width();
  left_.resize(grid_->cell_count());
  right_.resize(grid_->cell_count());
  for (int y = 0; y < grid_->height(); ++y) {
    const std::size_t row = grid_->index(0, y);
    int last = -1;
    for (int x = 0; x < w; ++x) {
      if (grid_->blocked(x, y)) last = x;
      left_[row + static_cast<std::size_t>(x)] = last;
    }
    last = w;
    for (int x = w - 1; x >= 0; --x) {
      if (grid_->blocked(x, y)) last = x;
      right_[row + static_cast<std::size_t>(x)] = last;
    }
  }
}

Eigen::Vector2i GridObstacles::clamped_cell(const Eigen::Vector2d& p) const {
  const Eigen::Vector2i c = grid_->world_to_cell(p);
  return {std::clamp(c.x(), 0, grid_->width() - 1), std::clamp(c.y(), 0, grid_->height() - 1)};
}

void GridObstacles::scan_row(const Eigen::Vector2d& p, int cx, int row, double& best_sq,
                             Eigen::Vector2d& best_point) const {
  // Scalar arithmetic on the squares' sides (what cell_box would give): this is the inner loop of
  // every exact clearance on a map, and unoptimised builds do not inline Eigen's temporaries.
  const double res = grid_->resolution(), ox = grid_->origin().x();
  const double y0 = grid_->origin().y() + res * row, y1 = y0 + res;
  const double qy = std::min(std::max(p.y(), y0), y1), dy = p.y() - qy;
  if (dy * dy >= best_sq) return;
  // The row's nearest blocked squares to p are the nearest left and right of p's column; the
  // neighbours' entries cover p lying on a column boundary up to rounding.
  const std::size_t i = grid_->index(cx, row);
  const int w = grid_->width();
  const std::int32_t candidates[4] = {left_[i], right_[i], cx > 0 ? left_[i - 1] : -1,
                                      cx + 1 < w ? right_[i + 1] : w};
  for (const std::int32_t x : candidates) {
    if (x < 0 || x >= w) continue;
    const double x0 = ox + res * x;
    const double qx = std::min(std::max(p.x(), x0), x0 + res), dx = p.x() - qx;
    const double d2 = dx * dx + dy * dy;
    if (d2 < best_sq) {
      best_sq = d2;
      best_point = {qx, qy};
    }
  }
}

bool GridObstacles::disc_free(const Eigen::Vector2d& p, double r) const {
  if (!p.allFinite()) return false;
  if (p.x() - r < extent_.min().x() || p.x() + r > extent_.max().x() || p.y() - r < extent_.min().y() ||
      p.y() + r > extent_.max().y()) {
    return false;
  }
  const Eigen::Vector2i c = clamped_cell(p);
  const std::size_t i = grid_->index(c.x(), c.y());
  const double d2 = edt_.squared_distance(i);
  if (d2 == DistanceTransform::kNoSite) return true;
  const double res = grid_->resolution();
  // p lies within sqrt(2)/2 cells of its cell's centre and every square within sqrt(2)/2 of its
  // own centre, so no blocked square is nearer than D - sqrt(2) cells.
  if ((std::sqrt(d2) - std::numbers::sqrt2 - kBoundSlack) * res >= r) return true;
  const int w = grid_->width();
  const std::int32_t o = edt_.nearest(i);
  const double r2 = r * r;
  if ((p - clamp_to_box(p, grid_->cell_box(o % w, o / w))).squaredNorm() < r2) return false;
  // Undecided: only rows within r of p can hold a square nearer than r.
  const double gy = grid_->world_to_grid(p).y();
  const int y0 = std::max(0, static_cast<int>(std::floor(gy - r / res)) - 1);
  const int y1 = std::min(grid_->height() - 1, static_cast<int>(std::floor(gy + r / res)) + 1);
  double best = r2;
  Eigen::Vector2d point;
  for (int row = y0; row <= y1; ++row) {
    scan_row(p, c.x(), row, best, point);
    if (best < r2) return false;
  }
  return true;
}

double GridObstacles::point_distance(const Eigen::Vector2d& p, Eigen::Vector2d& nearest) const {
  return nearest_within(p, kInf, nearest);
}

double GridObstacles::point_distance_up_to(const Eigen::Vector2d& p, double limit) const {
  Eigen::Vector2d nearest;
  return std::min(nearest_within(p, limit, nearest), limit);
}

double GridObstacles::nearest_within(const Eigen::Vector2d& p, double limit, Eigen::Vector2d& nearest) const {
  nearest = p;
  if (!p.allFinite() || !extent_.contains(p)) return 0.0;
  const Eigen::Vector2i c = clamped_cell(p);
  if (grid_->blocked(c.x(), c.y())) return 0.0;
  // The map's outside: the nearest of the four borders.
  const Eigen::Vector2d lo = p - extent_.min(), hi = extent_.max() - p;
  Eigen::Index klo = 0, khi = 0;
  const double dlo = lo.minCoeff(&klo), dhi = hi.minCoeff(&khi);
  double best_sq = sq(std::min(dlo, dhi));
  if (dlo <= dhi) {
    nearest[klo] = extent_.min()[klo];
  } else {
    nearest[khi] = extent_.max()[khi];
  }
  const std::size_t i = grid_->index(c.x(), c.y());
  const std::int32_t o = edt_.nearest(i);
  if (o < 0) return std::sqrt(best_sq);
  const double res = grid_->resolution();
  // No blocked square is nearer than D - sqrt(2) cells (see disc_free): beyond the limit, no scan.
  if ((std::sqrt(edt_.squared_distance(i)) - std::numbers::sqrt2 - kBoundSlack) * res >= limit) {
    return std::sqrt(best_sq);
  }
  const int w = grid_->width();
  const Eigen::Vector2d q = clamp_to_box(p, grid_->cell_box(o % w, o / w));
  if ((p - q).squaredNorm() < best_sq) {
    best_sq = (p - q).squaredNorm();
    nearest = q;
  }
  // The EDT's square is near-optimal; rows outward from p's settle the exact nearest. Row c.y +- k
  // is at least (k - 1) cells away; rows beyond the limit cannot change an answer capped there.
  const double limit_sq = sq(limit);
  for (int k = 0;; ++k) {
    if (k >= 1 && sq((k - 1) * res) >= std::min(best_sq, limit_sq)) break;
    const bool below = c.y() - k >= 0, above = c.y() + k < grid_->height();
    if (!below && !above) break;
    if (below) scan_row(p, c.x(), c.y() - k, best_sq, nearest);
    if (above && k > 0) scan_row(p, c.x(), c.y() + k, best_sq, nearest);
  }
  return std::sqrt(best_sq);
}

bool GridObstacles::polygon_free(const Eigen::Vector2d* v, int n) const {
  for (int k = 0; k < n; ++k) {
    if (!v[k].allFinite() || !extent_.contains(v[k])) return false;
  }
  const Eigen::AlignedBox2d aabb = bounding_box(v, n);
  const Eigen::Vector2i c0 = clamped_cell(aabb.min()), c1 = clamped_cell(aabb.max());
  const int x0 = std::max(0, c0.x() - 1), x1 = std::min(grid_->width() - 1, c1.x() + 1);
  const int y0 = std::max(0, c0.y() - 1), y1 = std::min(grid_->height() - 1, c1.y() + 1);
  for (int row = y0; row <= y1; ++row) {
    const std::size_t base = grid_->index(0, row);
    for (int x = right_[base + static_cast<std::size_t>(x0)]; x <= x1;
         x = x + 1 <= x1 ? right_[base + static_cast<std::size_t>(x) + 1] : x1 + 1) {
      const Eigen::AlignedBox2d box = grid_->cell_box(x, row);
      if (box.intersects(aabb) && polygon_meets_box(v, n, box)) return false;
    }
  }
  return true;
}

double GridObstacles::polygon_distance(const Eigen::Vector2d* v, int n, Eigen::Vector2d& robot_point,
                                       Eigen::Vector2d& obstacle_point) const {
  robot_point = obstacle_point = v[0];
  if (!polygon_free(v, n)) return 0.0;
  // Vertices against every square and the outside: point_distance settles them exactly.
  double best = kInf;
  for (int k = 0; k < n; ++k) {
    Eigen::Vector2d q;
    const double d = point_distance(v[k], q);
    if (d < best) {
      best = d;
      robot_point = v[k];
      obstacle_point = q;
    }
  }
  if (best <= 0.0) return 0.0;
  // What remains is a square's corner against an edge's interior, for squares within `best`.
  const Eigen::AlignedBox2d aabb = bounding_box(v, n);
  const Eigen::Vector2d reach = Eigen::Vector2d::Constant(best);
  const Eigen::Vector2i c0 = clamped_cell(aabb.min() - reach), c1 = clamped_cell(aabb.max() + reach);
  double best_sq = best * best;
  for (int row = c0.y(); row <= c1.y(); ++row) {
    const std::size_t base = grid_->index(0, row);
    for (int x = right_[base + static_cast<std::size_t>(c0.x())]; x <= c1.x();
         x = x + 1 <= c1.x() ? right_[base + static_cast<std::size_t>(x) + 1] : c1.x() + 1) {
      const Eigen::AlignedBox2d box = grid_->cell_box(x, row);
      if (box.squaredExteriorDistance(aabb) >= best_sq) continue;
      for (int corner = 0; corner < 4; ++corner) {
        const Eigen::Vector2d cp = box.corner(static_cast<Eigen::AlignedBox2d::CornerType>(corner));
        for (int i = 0, j = n - 1; i < n; j = i++) {
          Eigen::Vector2d on_edge;
          const double d2 = sq_point_segment(cp, v[j], v[i], on_edge);
          if (d2 < best_sq) {
            best_sq = d2;
            robot_point = on_edge;
            obstacle_point = cp;
          }
        }
      }
    }
  }
  return std::sqrt(best_sq);
}

}  // namespace amp::world
