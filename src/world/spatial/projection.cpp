#include "world/spatial/projection.hpp"

#include <algorithm>
#include <cmath>

namespace amp::world::detail {

namespace {
// Relative projected area below which a triangle counts as edge-on (the walls of a prism).
constexpr double kDegenerateArea = 1e-12;
// |axis . z| above which a cylinder is drawn as its circle.
constexpr double kVerticalAxis = 1.0 - 1e-9;

double cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
}
}  // namespace

Polygon convex_hull_xy(const std::vector<Eigen::Vector3d>& points) {
  std::vector<Eigen::Vector2d> p;
  p.reserve(points.size());
  for (const Eigen::Vector3d& q : points) p.push_back(q.head<2>());
  std::sort(p.begin(), p.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  p.erase(std::unique(p.begin(), p.end()), p.end());
  Polygon hull;
  if (p.size() < 3) {
    hull.vertices = p;
    return hull;
  }
  std::vector<Eigen::Vector2d> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {  // lower chain
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i > 0; --i) {  // upper chain
    while (k >= t && cross(h[k - 2], h[k - 1], p[i - 1]) <= 0) --k;
    h[k++] = p[i - 1];
  }
  h.resize(k - 1);
  hull.vertices = std::move(h);
  return hull;
}

void project_triangles(const TriangleMesh& mesh, const Eigen::Isometry3d& pose, Shapes2d& out) {
  std::vector<Eigen::Vector2d> v;
  v.reserve(mesh.vertices.size());
  Eigen::AlignedBox2d box;
  for (const Eigen::Vector3d& p : mesh.vertices) {
    v.push_back((pose * p).head<2>());
    box.extend(v.back());
  }
  const double eps = kDegenerateArea * std::max(1.0, box.sizes().squaredNorm());
  double up_area = 0.0, down_area = 0.0;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const double a = 0.5 * cross(v[t[0]], v[t[1]], v[t[2]]);
    if (a > eps) up_area += a;
    if (a < -eps) down_area -= a;
  }
  // A closed oriented surface covers its shadow as often from above as from below.
  const bool oriented = std::abs(up_area - down_area) <= 1e-6 * std::max(1.0, up_area + down_area);
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const double a = 0.5 * cross(v[t[0]], v[t[1]], v[t[2]]);
    if (std::abs(a) <= eps || (oriented && a < 0.0)) continue;
    Polygon poly;
    poly.vertices = {v[t[0]], v[t[1]], v[t[2]]};
    if (a < 0.0) std::swap(poly.vertices[1], poly.vertices[2]);
    out.polygons.push_back(std::move(poly));
  }
}

void project_solid(const Solid& solid, const Eigen::Isometry3d& parent, bool mesh_triangles, Shapes2d& out) {
  const Eigen::Isometry3d pose = parent * solid.pose;
  if (solid.kind == Solid::Kind::kSphere) {
    out.circles.push_back({pose.translation().head<2>(), solid.radius});
  } else if (solid.kind == Solid::Kind::kCylinder && std::abs(pose.linear()(2, 2)) > kVerticalAxis) {
    out.circles.push_back({pose.translation().head<2>(), solid.radius});
  } else if (solid.kind == Solid::Kind::kMesh && mesh_triangles) {
    project_triangles(*solid.mesh, pose, out);
  } else {
    Polygon hull = convex_hull_xy(solid.hull_points(parent));
    if (hull.vertices.size() >= 3) out.polygons.push_back(std::move(hull));
  }
}

}  // namespace amp::world::detail
