#include "amp/nav/polygon_nav_world.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "amp/core/error.hpp"
#include "amp/nav/grid_traversal.hpp"
#include "amp/nav/world_event.hpp"
#include "amp/world/polygon_geometry.hpp"

namespace amp::nav {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Shapes of a vanish event match world obstacles up to this (coordinates as written in YAML).
constexpr double kShapeMatchTolerance = 1e-9;

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// First t >= 0 where p + t d meets the closed segment ab; kInf if never.
double ray_segment(const Eigen::Vector2d& p, const Eigen::Vector2d& d, const Eigen::Vector2d& a,
                   const Eigen::Vector2d& b) {
  const Eigen::Vector2d e = b - a, ap = a - p;
  const double denom = cross(d, e);
  if (denom != 0.0) {
    const double t = cross(ap, e) / denom;
    const double s = cross(ap, d) / denom;
    return t >= 0.0 && s >= 0.0 && s <= 1.0 ? t : kInf;
  }
  if (cross(ap, d) != 0.0) return kInf;  // parallel, not collinear
  const double ta = ap.dot(d), tb = (b - p).dot(d);
  if (std::max(ta, tb) < 0.0) return kInf;
  return std::max(0.0, std::min(ta, tb));
}

// First t >= 0 where p + t d meets the closed disc; kInf if never.
double ray_circle(const Eigen::Vector2d& p, const Eigen::Vector2d& d, const world::Circle& c) {
  const Eigen::Vector2d f = p - c.center;
  const double b = f.dot(d);
  const double cc = f.squaredNorm() - c.radius * c.radius;
  if (cc <= 0.0) return 0.0;
  const double disc = b * b - cc;
  if (disc < 0.0 || b > 0.0) return kInf;  // missed, or the circle lies behind
  return -b - std::sqrt(disc);
}

// Distance from p (inside the closed box) along d to the box's border.
double exit_distance(const Eigen::AlignedBox2d& box, const Eigen::Vector2d& p, const Eigen::Vector2d& d) {
  double t = kInf;
  for (int k = 0; k < 2; ++k) {
    if (d[k] > 0.0) t = std::min(t, (box.max()[k] - p[k]) / d[k]);
    if (d[k] < 0.0) t = std::min(t, (box.min()[k] - p[k]) / d[k]);
  }
  return std::max(0.0, t);
}

// Where p + t d enters and leaves the closed box (slab test); false when it misses.
bool clip_to_box(const Eigen::AlignedBox2d& box, const Eigen::Vector2d& p, const Eigen::Vector2d& d, double& t0,
                 double& t1) {
  t0 = 0.0;
  t1 = kInf;
  for (int k = 0; k < 2; ++k) {
    if (d[k] == 0.0) {
      if (p[k] < box.min()[k] || p[k] > box.max()[k]) return false;
      continue;
    }
    double a = (box.min()[k] - p[k]) / d[k], b = (box.max()[k] - p[k]) / d[k];
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
  }
  return t0 <= t1;
}

bool same_polygon(const world::Polygon& a, const world::Polygon& b) {
  if (a.vertices.size() != b.vertices.size()) return false;
  for (std::size_t i = 0; i < a.vertices.size(); ++i) {
    if ((a.vertices[i] - b.vertices[i]).lpNorm<Eigen::Infinity>() > kShapeMatchTolerance) return false;
  }
  return true;
}

bool same_circle(const world::Circle& a, const world::Circle& b) {
  return (a.center - b.center).lpNorm<Eigen::Infinity>() <= kShapeMatchTolerance &&
         std::abs(a.radius - b.radius) <= kShapeMatchTolerance;
}

std::string point_text(const Eigen::Vector2d& p) {
  return "(" + std::to_string(p.x()) + ", " + std::to_string(p.y()) + ")";
}

}  // namespace

PolygonNavWorld::PolygonNavWorld(std::shared_ptr<const world::PlanarWorld> world) : world_(std::move(world)) {
  if (!world_) throw ParameterError("PolygonNavWorld: no world");
  int first = 0;
  for (const world::Polygon& poly : world_->obstacles().polygons) {
    polygon_first_edge_.push_back(first);
    first += static_cast<int>(poly.vertices.size());
  }
}

PolygonNavWorld::PolygonNavWorld(world::Shapes2d obstacles, const Eigen::AlignedBox2d& bounds)
    : PolygonNavWorld(std::make_shared<const world::PlanarWorld>(std::move(obstacles), bounds)) {}

bool PolygonNavWorld::inside_obstacle(const Eigen::Vector2d& p) const {
  const world::Shapes2d& obstacles = world_->obstacles();
  for (std::size_t i = 0; i < obstacles.polygons.size(); ++i) {
    if (!world_->polygon_boxes()[i].contains(p)) continue;
    if (world::point_in_polygon(p, obstacles.polygons[i].vertices)) return true;
  }
  for (const world::Circle& c : obstacles.circles) {
    if ((p - c.center).squaredNorm() <= c.radius * c.radius) return true;
  }
  return false;
}

bool PolygonNavWorld::disc_free(const Eigen::Vector2d& p, double r) const {
  if (!p.allFinite() || !(r >= 0.0)) return false;
  const Eigen::AlignedBox2d& b = bounds();
  if (p.x() - r < b.min().x() || p.x() + r > b.max().x() || p.y() - r < b.min().y() || p.y() + r > b.max().y()) {
    return false;
  }
  const world::PlanarGrid& grid = world_->grid();
  const double r2 = r * r;
  int x0, y0, x1, y1;
  const Eigen::Vector2d reach = Eigen::Vector2d::Constant(r);
  if (grid.cell_range(Eigen::AlignedBox2d(p - reach, p + reach), x0, y0, x1, y1)) {
    const auto& edges = world_->edges();
    const auto& circles = world_->obstacles().circles;
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const int cell = grid.cell_index(x, y);
        for (const int e : grid.edges_in(cell)) {
          if (world::point_segment_distance_sq(p, edges[e].a, edges[e].b) < r2) return false;
        }
        for (const int c : grid.circles_in(cell)) {
          const double reach_c = circles[c].radius + r;
          if ((p - circles[c].center).squaredNorm() < reach_c * reach_c) return false;
        }
      }
    }
  }
  // No boundary within r: the disc is free unless its centre is inside a shape.
  return !inside_obstacle(p);
}

NearestObstacle PolygonNavWorld::nearest_obstacle(const Eigen::Vector2d& p) const {
  NearestObstacle out{0.0, p};
  const Eigen::AlignedBox2d& b = bounds();
  if (!p.allFinite() || !b.contains(p) || inside_obstacle(p)) return out;
  // The outside: the nearest of the four borders.
  const Eigen::Vector2d lo = p - b.min(), hi = b.max() - p;
  Eigen::Index klo = 0, khi = 0;
  const double dlo = lo.minCoeff(&klo), dhi = hi.minCoeff(&khi);
  if (dlo <= dhi) {
    out.point[klo] = b.min()[klo];
  } else {
    out.point[khi] = b.max()[khi];
  }
  double best_sq = std::min(dlo, dhi) * std::min(dlo, dhi);
  const auto& edges = world_->edges();
  Eigen::Vector2d q;
  const auto try_edge = [&](const world::PlanarEdge& e) {
    if (e.box.squaredExteriorDistance(p) >= best_sq) return;
    const double d2 = world::point_segment_distance_sq(p, e.a, e.b, &q);
    if (d2 < best_sq) {
      best_sq = d2;
      out.point = q;
    }
  };
  const world::Shapes2d& obstacles = world_->obstacles();
  for (std::size_t i = 0; i < obstacles.polygons.size(); ++i) {
    if (world_->polygon_boxes()[i].squaredExteriorDistance(p) >= best_sq) continue;
    const int first = polygon_first_edge_[i];
    const int last = first + static_cast<int>(obstacles.polygons[i].vertices.size());
    for (int e = first; e < last; ++e) try_edge(edges[e]);
  }
  for (int e = world_->first_segment_edge(); e < static_cast<int>(edges.size()); ++e) try_edge(edges[e]);
  double best = std::sqrt(best_sq);
  for (const world::Circle& c : obstacles.circles) {
    const Eigen::Vector2d v = p - c.center;
    const double n = v.norm();
    if (n - c.radius < best) {
      best = n - c.radius;
      out.point = c.center + c.radius * v / n;  // n > radius: p is outside the circle
    }
  }
  out.distance = best;
  return out;
}

double PolygonNavWorld::ray_cast(const Eigen::Vector2d& p, const Eigen::Vector2d& dir, double max_range) const {
  const Eigen::AlignedBox2d& b = bounds();
  // The outside is closed, as the shapes are: a ray from the border touches it at once.
  const bool strictly_inside = (p.array() > b.min().array()).all() && (p.array() < b.max().array()).all();
  if (!strictly_inside || inside_obstacle(p)) return 0.0;
  double best = std::min(max_range, exit_distance(b, p, dir));
  const world::PlanarGrid& grid = world_->grid();
  double t0, t1;
  if (grid.empty() || !clip_to_box(grid.extent(), p, dir, t0, t1) || t0 >= best) return best;
  // Walk the broad-phase cells from where the ray enters the grid; a hit found in a cell is final
  // once the ray has left that cell (later cells lie farther along it).
  const double cell = grid.cell_size();
  const Eigen::Vector2d start = (p + t0 * dir - grid.extent().min()) / cell;
  GridTraversal walk(start.cwiseMax(0.0), dir / cell);
  const auto& edges = world_->edges();
  const auto& circles = world_->obstacles().circles;
  for (;;) {
    const int x = std::clamp(walk.x(), 0, grid.nx() - 1), y = std::clamp(walk.y(), 0, grid.ny() - 1);
    const int id = grid.cell_index(x, y);
    for (const int e : grid.edges_in(id)) best = std::min(best, ray_segment(p, dir, edges[e].a, edges[e].b));
    for (const int c : grid.circles_in(id)) best = std::min(best, ray_circle(p, dir, circles[c]));
    const double t_exit = t0 + walk.t_exit();
    if (best <= t_exit || t_exit >= t1) break;
    walk.next();
    if (walk.x() < 0 || walk.y() < 0 || walk.x() >= grid.nx() || walk.y() >= grid.ny()) break;
  }
  return best;
}

std::shared_ptr<const NavWorld> PolygonNavWorld::changed(const ObstacleChange& change) const {
  if (!change.cells.empty()) throw ParameterError("map cells can only change on a map world, not a polygon world");
  if (!change.shapes.segments.empty()) throw ParameterError("segment walls cannot appear or vanish");
  world::Shapes2d shapes = world_->obstacles();
  if (change.action == ObstacleChange::Action::kAppear) {
    shapes.polygons.insert(shapes.polygons.end(), change.shapes.polygons.begin(), change.shapes.polygons.end());
    shapes.circles.insert(shapes.circles.end(), change.shapes.circles.begin(), change.shapes.circles.end());
  } else {
    for (const world::Polygon& gone : change.shapes.polygons) {
      const auto it = std::find_if(shapes.polygons.begin(), shapes.polygons.end(),
                                   [&](const world::Polygon& q) { return same_polygon(q, gone); });
      if (it == shapes.polygons.end()) {
        throw ParameterError("the vanishing polygon with first vertex " + point_text(gone.vertices.front()) +
                             " is not in the world");
      }
      shapes.polygons.erase(it);
    }
    for (const world::Circle& gone : change.shapes.circles) {
      const auto it = std::find_if(shapes.circles.begin(), shapes.circles.end(),
                                   [&](const world::Circle& q) { return same_circle(q, gone); });
      if (it == shapes.circles.end()) {
        throw ParameterError("the vanishing circle at " + point_text(gone.center) + " is not in the world");
      }
      shapes.circles.erase(it);
    }
  }
  return std::make_shared<const PolygonNavWorld>(std::move(shapes), bounds());
}

}  // namespace amp::nav
