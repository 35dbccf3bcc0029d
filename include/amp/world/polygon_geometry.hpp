#pragma once
#include <algorithm>
#include <span>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "amp/world/shapes2d.hpp"

// Tiny exact predicates and distances on planar points, segments and simple polygons. The hot ones
// (orientation, segment intersection, point in polygon) are inline: the planar checker calls them
// millions of times per second. Sets are closed: touching counts as intersecting.
namespace amp::world {

// Twice the signed area of triangle abc: > 0 when a, b, c turn counter-clockwise.
inline double orient2d(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

// p, known to be collinear with segment ab, lies within its bounding box (so on the segment).
inline bool on_collinear_segment(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& p) {
  return std::min(a.x(), b.x()) <= p.x() && p.x() <= std::max(a.x(), b.x()) && std::min(a.y(), b.y()) <= p.y() &&
         p.y() <= std::max(a.y(), b.y());
}

// Closed segments ab and cd share at least one point.
inline bool segments_intersect(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                               const Eigen::Vector2d& d) {
  const double d1 = orient2d(c, d, a);
  const double d2 = orient2d(c, d, b);
  if ((d1 > 0.0 && d2 > 0.0) || (d1 < 0.0 && d2 < 0.0)) return false;  // early exit: both on one side
  const double d3 = orient2d(a, b, c);
  const double d4 = orient2d(a, b, d);
  if ((d3 > 0.0 && d4 > 0.0) || (d3 < 0.0 && d4 < 0.0)) return false;
  if (d1 != 0.0 && d2 != 0.0 && d3 != 0.0 && d4 != 0.0) return true;  // proper crossing
  // An endpoint lies on the other segment's line: touching, or collinear overlap.
  return (d1 == 0.0 && on_collinear_segment(c, d, a)) || (d2 == 0.0 && on_collinear_segment(c, d, b)) ||
         (d3 == 0.0 && on_collinear_segment(a, b, c)) || (d4 == 0.0 && on_collinear_segment(a, b, d));
}

// Crossing-number test (ray towards +x). Points exactly on the boundary may go either way; callers
// that need closed sets test the boundary separately (edge intersection or distance).
inline bool point_in_polygon(const Eigen::Vector2d& p, std::span<const Eigen::Vector2d> v) {
  bool inside = false;
  const std::size_t n = v.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Eigen::Vector2d& a = v[i];
    const Eigen::Vector2d& b = v[j];
    if ((a.y() > p.y()) != (b.y() > p.y())) {
      const double x = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (p.x() < x) inside = !inside;
    }
  }
  return inside;
}

// Squared distance from p to segment ab; `closest` (optional) receives the nearest point of ab.
double point_segment_distance_sq(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                 Eigen::Vector2d* closest = nullptr);

// Squared distance between segments ab and cd (0 when they intersect) with the nearest points.
double segment_segment_distance_sq(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                                   const Eigen::Vector2d& d, Eigen::Vector2d* on_ab = nullptr,
                                   Eigen::Vector2d* on_cd = nullptr);

// Squared distance from p to the boundary of polygon v (closed), with the nearest boundary point.
double polygon_boundary_distance_sq(const Eigen::Vector2d& p, std::span<const Eigen::Vector2d> v,
                                    Eigen::Vector2d* closest = nullptr);

// Signed area (> 0 for counter-clockwise vertex order).
double signed_area(std::span<const Eigen::Vector2d> v);
bool is_convex(std::span<const Eigen::Vector2d> v);
// No two edges meet except consecutive ones at their shared vertex (O(n^2), for loading only).
// On failure `bad_i`/`bad_j` (optional) name two offending edges (edge i runs from v[i] to v[i+1]).
bool is_simple(std::span<const Eigen::Vector2d> v, int* bad_i = nullptr, int* bad_j = nullptr);
Eigen::AlignedBox2d bounding_box(std::span<const Eigen::Vector2d> v);

// Closed polygons overlap (edges meet, or one contains the other).
bool polygons_overlap(std::span<const Eigen::Vector2d> a, std::span<const Eigen::Vector2d> b);
// Closed polygon and closed disc overlap.
bool polygon_circle_overlap(std::span<const Eigen::Vector2d> v, const Eigen::Vector2d& center, double radius);

// Convex hull (Andrew's monotone chain), counter-clockwise, without collinear points.
std::vector<Eigen::Vector2d> convex_hull(std::vector<Eigen::Vector2d> points);
// Smallest width of a point set over all directions (rotating calipers on the hull); 0 for < 3 hull points.
double minimum_width(const std::vector<Eigen::Vector2d>& points);

// p placed by pose (rotation by theta, then translation).
inline Eigen::Vector2d transform_point(const Pose2& pose, double c, double s, const Eigen::Vector2d& p) {
  return {pose.x + c * p.x() - s * p.y(), pose.y + s * p.x() + c * p.y()};
}

}  // namespace amp::world
