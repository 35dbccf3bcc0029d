#include "amp/world/planar_world.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "amp/core/error.hpp"
#include "amp/core/number_text.hpp"
#include "amp/world/polygon_geometry.hpp"

namespace amp::world {

namespace {
// A polygon whose area is below this fraction of its bounding box's squared diagonal is degenerate
// (collinear vertices up to rounding).
constexpr double kMinRelativeArea = 1e-12;

// All vertices on one line (up to rounding). Tested before simplicity: the edges of such a polygon
// fold back onto each other, and "zero area" says what is wrong better than "self-intersecting".
bool all_collinear(const std::vector<Eigen::Vector2d>& v, double diag_sq) {
  std::size_t far = 0;
  for (std::size_t k = 1; k < v.size(); ++k) {
    if ((v[k] - v[0]).squaredNorm() > (v[far] - v[0]).squaredNorm()) far = k;
  }
  const Eigen::Vector2d d = v[far] - v[0];
  const double d_sq = d.squaredNorm();
  if (d_sq == 0.0) return true;
  for (const Eigen::Vector2d& p : v) {
    const double cross = d.x() * (p - v[0]).y() - d.y() * (p - v[0]).x();  // |d| * distance of p to the line
    if (cross * cross > kMinRelativeArea * kMinRelativeArea * diag_sq * d_sq) return false;
  }
  return true;
}

// "obstacle polygon 3: " or, for an anonymous single shape, "".
std::string label(const std::string& what, const char* kind, std::size_t i) {
  return what.empty() ? std::string() : what + " " + kind + " " + std::to_string(i) + ": ";
}
}  // namespace

void validate_shapes(const Shapes2d& shapes, std::string_view what, double min_radius) {
  const std::string w(what);
  for (std::size_t i = 0; i < shapes.polygons.size(); ++i) {
    const auto& v = shapes.polygons[i].vertices;
    const std::string name = label(w, "polygon", i);
    if (v.size() < 3) throw ParameterError(name + "needs at least 3 vertices, got " + std::to_string(v.size()));
    for (const auto& p : v) {
      if (!p.allFinite()) throw ParameterError(name + "vertex coordinates must be finite");
    }
    const double diag_sq = bounding_box(v).sizes().squaredNorm();
    if (all_collinear(v, diag_sq)) throw ParameterError(name + "zero area (all vertices on one line)");
    int bad_i = 0, bad_j = 0;
    if (!is_simple(v, &bad_i, &bad_j)) {
      throw ParameterError(name + "self-intersecting edges " + std::to_string(bad_i) + " and " + std::to_string(bad_j));
    }
    const double area = signed_area(v);
    if (!(std::abs(area) > kMinRelativeArea * diag_sq)) {
      throw ParameterError(name + "zero area (area " + core::number_text(area) + ")");
    }
  }
  for (std::size_t i = 0; i < shapes.circles.size(); ++i) {
    const Circle& c = shapes.circles[i];
    const std::string name = label(w, "circle", i);
    if (!c.center.allFinite()) throw ParameterError(name + "centre must be finite");
    if (!std::isfinite(c.radius) || !(c.radius > min_radius)) {
      throw ParameterError(name + "radius must be " + (min_radius < 0.0 ? "non-negative" : "positive") + ", got " +
                           core::number_text(c.radius));
    }
  }
}

PlanarWorld::PlanarWorld(Shapes2d obstacles, Eigen::AlignedBox2d bounds)
    : obstacles_(std::move(obstacles)), bounds_(bounds) {
  if (!bounds_.min().allFinite() || !bounds_.max().allFinite() || !(bounds_.min().array() < bounds_.max().array()).all()) {
    throw ParameterError("bounds: min must be below max in every coordinate and finite");
  }
  validate_shapes(obstacles_, "obstacle");
  polygon_boxes_.reserve(obstacles_.polygons.size());
  for (std::size_t p = 0; p < obstacles_.polygons.size(); ++p) {
    const auto& v = obstacles_.polygons[p].vertices;
    polygon_boxes_.push_back(bounding_box(v));
    for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
      PlanarEdge e;
      e.a = v[j];
      e.b = v[i];
      e.box = Eigen::AlignedBox2d(v[j].cwiseMin(v[i]), v[j].cwiseMax(v[i]));
      e.polygon = static_cast<int>(p);
      edges_.push_back(e);
    }
  }
  // Segment walls join the edge list with no polygon (-1): they block, but enclose nothing.
  first_segment_edge_ = static_cast<int>(edges_.size());
  for (const Segment& s : obstacles_.segments) {
    if (!s.a.allFinite() || !s.b.allFinite()) throw ParameterError("obstacle segment: coordinates must be finite");
    PlanarEdge e;
    e.a = s.a;
    e.b = s.b;
    e.box = Eigen::AlignedBox2d(s.a.cwiseMin(s.b), s.a.cwiseMax(s.b));
    e.polygon = -1;
    edges_.push_back(e);
  }
  circle_boxes_.reserve(obstacles_.circles.size());
  for (const Circle& c : obstacles_.circles) {
    const Eigen::Vector2d r = Eigen::Vector2d::Constant(c.radius);
    circle_boxes_.emplace_back(c.center - r, c.center + r);
  }
  grid_ = PlanarGrid(edges_, obstacles_, polygon_boxes_, circle_boxes_);
}

bool PlanarWorld::point_in_obstacle_polygon(const Eigen::Vector2d& p, std::vector<int>& scratch) const {
  const int cell = grid_.cell_of(p);
  if (cell < 0) return false;
  const Eigen::Vector2d r = grid_.reference_point(cell);
  scratch.clear();
  for (int id : grid_.polygons_around(cell)) scratch.push_back(id);
  for (int id : grid_.edges_in(cell)) {
    const PlanarEdge& e = edges_[id];
    if (e.polygon < 0) continue;  // a segment wall encloses nothing
    // Half-open rule on both lines: a vertex exactly on a line counts on the positive side, so a
    // crossing through a shared vertex is counted once.
    if ((orient2d(r, p, e.a) > 0.0) == (orient2d(r, p, e.b) > 0.0)) continue;
    if ((orient2d(e.a, e.b, r) > 0.0) == (orient2d(e.a, e.b, p) > 0.0)) continue;
    scratch.push_back(e.polygon);
  }
  if (scratch.empty()) return false;
  // p is inside polygon q iff q's count (1 if it holds r, plus its crossings) is odd.
  std::sort(scratch.begin(), scratch.end());
  for (std::size_t i = 0; i < scratch.size();) {
    std::size_t j = i;
    while (j < scratch.size() && scratch[j] == scratch[i]) ++j;
    if ((j - i) % 2 == 1) return true;
    i = j;
  }
  return false;
}

}  // namespace amp::world
