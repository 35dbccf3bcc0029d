#include "amp/world/polygon_geometry.hpp"

#include <cmath>
#include <limits>

namespace amp::world {

double point_segment_distance_sq(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                 Eigen::Vector2d* closest) {
  const Eigen::Vector2d ab = b - a;
  const double len_sq = ab.squaredNorm();
  double t = len_sq > 0.0 ? (p - a).dot(ab) / len_sq : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  const Eigen::Vector2d q = a + t * ab;
  if (closest != nullptr) *closest = q;
  return (p - q).squaredNorm();
}

double segment_segment_distance_sq(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                                   const Eigen::Vector2d& d, Eigen::Vector2d* on_ab, Eigen::Vector2d* on_cd) {
  if (segments_intersect(a, b, c, d)) {
    // Any common point will do; the line intersection when the segments are not parallel.
    Eigen::Vector2d x = a;
    const double denom = orient2d({0.0, 0.0}, b - a, d - c);
    if (denom != 0.0) {
      const double t = std::clamp(orient2d({0.0, 0.0}, c - a, d - c) / denom, 0.0, 1.0);
      x = a + t * (b - a);
    } else if (on_collinear_segment(c, d, a)) {
      x = a;
    } else if (on_collinear_segment(c, d, b)) {
      x = b;
    } else {
      x = c;
    }
    if (on_ab != nullptr) *on_ab = x;
    if (on_cd != nullptr) *on_cd = x;
    return 0.0;
  }
  // Disjoint segments: the minimum is attained at an endpoint of one of them.
  Eigen::Vector2d q;
  double best = point_segment_distance_sq(a, c, d, &q);
  Eigen::Vector2d pa = a, pc = q;
  double v = point_segment_distance_sq(b, c, d, &q);
  if (v < best) best = v, pa = b, pc = q;
  v = point_segment_distance_sq(c, a, b, &q);
  if (v < best) best = v, pa = q, pc = c;
  v = point_segment_distance_sq(d, a, b, &q);
  if (v < best) best = v, pa = q, pc = d;
  if (on_ab != nullptr) *on_ab = pa;
  if (on_cd != nullptr) *on_cd = pc;
  return best;
}

double polygon_boundary_distance_sq(const Eigen::Vector2d& p, std::span<const Eigen::Vector2d> v,
                                    Eigen::Vector2d* closest) {
  double best = std::numeric_limits<double>::infinity();
  Eigen::Vector2d q;
  for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
    const double d = point_segment_distance_sq(p, v[j], v[i], &q);
    if (d < best) {
      best = d;
      if (closest != nullptr) *closest = q;
    }
  }
  return best;
}

double signed_area(std::span<const Eigen::Vector2d> v) {
  double twice = 0.0;
  for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
    twice += v[j].x() * v[i].y() - v[i].x() * v[j].y();
  }
  return 0.5 * twice;
}

bool is_convex(std::span<const Eigen::Vector2d> v) {
  const std::size_t n = v.size();
  if (n < 3) return false;
  bool pos = false, neg = false;
  for (std::size_t i = 0; i < n; ++i) {
    const double o = orient2d(v[i], v[(i + 1) % n], v[(i + 2) % n]);
    pos = pos || o > 0.0;
    neg = neg || o < 0.0;
  }
  return !(pos && neg) && is_simple(v);
}

bool is_simple(std::span<const Eigen::Vector2d> v, int* bad_i, int* bad_j) {
  const int n = static_cast<int>(v.size());
  auto fail = [&](int i, int j) {
    if (bad_i != nullptr) *bad_i = i;
    if (bad_j != nullptr) *bad_j = j;
    return false;
  };
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d& a = v[i];
    const Eigen::Vector2d& b = v[(i + 1) % n];
    if (a == b) return fail(i, i);  // zero-length edge
    for (int j = i + 1; j < n; ++j) {
      const Eigen::Vector2d& c = v[j];
      const Eigen::Vector2d& d = v[(j + 1) % n];
      const bool next = j == i + 1;
      const bool prev = i == 0 && j == n - 1;
      if (!next && !prev) {
        if (segments_intersect(a, b, c, d)) return fail(i, j);
        continue;
      }
      // Consecutive edges share one vertex; they must not fold back onto each other.
      const Eigen::Vector2d& shared = next ? b : a;
      const Eigen::Vector2d& far_1 = next ? a : b;
      const Eigen::Vector2d& far_2 = next ? d : c;
      if (orient2d(far_1, shared, far_2) == 0.0 && (far_1 - shared).dot(far_2 - shared) > 0.0) return fail(i, j);
    }
  }
  return true;
}

Eigen::AlignedBox2d bounding_box(std::span<const Eigen::Vector2d> v) {
  Eigen::AlignedBox2d box;
  for (const Eigen::Vector2d& p : v) box.extend(p);
  return box;
}

bool polygons_overlap(std::span<const Eigen::Vector2d> a, std::span<const Eigen::Vector2d> b) {
  for (std::size_t i = 0, j = a.size() - 1; i < a.size(); j = i++) {
    for (std::size_t k = 0, l = b.size() - 1; k < b.size(); l = k++) {
      if (segments_intersect(a[j], a[i], b[l], b[k])) return true;
    }
  }
  // No boundary contact: overlapping only if one lies wholly inside the other.
  return point_in_polygon(a[0], b) || point_in_polygon(b[0], a);
}

bool polygon_circle_overlap(std::span<const Eigen::Vector2d> v, const Eigen::Vector2d& center, double radius) {
  return polygon_boundary_distance_sq(center, v) <= radius * radius || point_in_polygon(center, v);
}

std::vector<Eigen::Vector2d> convex_hull(std::vector<Eigen::Vector2d> points) {
  std::sort(points.begin(), points.end(), [](const Eigen::Vector2d& p, const Eigen::Vector2d& q) {
    return p.x() < q.x() || (p.x() == q.x() && p.y() < q.y());
  });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return points;
  std::vector<Eigen::Vector2d> hull(2 * points.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {  // lower hull
    while (k >= 2 && orient2d(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  for (std::size_t i = points.size() - 1, t = k + 1; i-- > 0;) {  // upper hull
    while (k >= t && orient2d(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

double minimum_width(const std::vector<Eigen::Vector2d>& points) {
  const std::vector<Eigen::Vector2d> hull = convex_hull(points);
  if (hull.size() < 3) return 0.0;
  // The minimum-width strip has one side flush with a hull edge: try every edge (O(h^2), h small).
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Eigen::Vector2d& a = hull[i];
    const Eigen::Vector2d& b = hull[(i + 1) % hull.size()];
    const double len = (b - a).norm();
    double far = 0.0;
    for (const Eigen::Vector2d& p : hull) far = std::max(far, std::abs(orient2d(a, b, p)) / len);
    best = std::min(best, far);
  }
  return best;
}

}  // namespace amp::world
