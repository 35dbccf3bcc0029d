#include "world/spatial/projection.hpp"

#include <algorithm>
#include <array>
#include <set>
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

namespace {
// Sutherland-Hodgman against one plane: keeps the points with sign * (z - level) >= 0.
void clip_z(std::vector<Eigen::Vector3d>& poly, double level, double sign, std::vector<Eigen::Vector3d>& scratch) {
  scratch.clear();
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Eigen::Vector3d& a = poly[i];
    const Eigen::Vector3d& b = poly[(i + 1) % poly.size()];
    const double da = sign * (a.z() - level), db = sign * (b.z() - level);
    if (da >= 0.0) scratch.push_back(a);
    if ((da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0)) {
      Eigen::Vector3d c = a + (da / (da - db)) * (b - a);
      c.z() = level;
      scratch.push_back(c);
    }
  }
  poly.swap(scratch);
}

bool before(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); }
}  // namespace

void project_slab_surface(const TriangleMesh& mesh, double z0, double z1, Shapes2d& out) {
  std::set<std::array<double, 4>> seen;  // segments already kept, endpoints ordered
  const auto keep = [&](Eigen::Vector2d a, Eigen::Vector2d b) {
    if (a == b) return;
    if (before(b, a)) std::swap(a, b);
    if (seen.insert({a.x(), a.y(), b.x(), b.y()}).second) out.segments.push_back({a, b});
  };
  std::vector<Eigen::Vector3d> poly, scratch;
  std::vector<Eigen::Vector2d> flat;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    poly = {mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]};
    // A flat triangle in the plane of the robot's bottom or top face overlaps that face wherever
    // their shadows meet (FCL reports coplanar overlap as contact): it blocks as a region.
    const double z = poly[0].z();
    const bool in_cap_plane = poly[1].z() == z && poly[2].z() == z && (z == z0 || z == z1);
    clip_z(poly, z0, 1.0, scratch);
    if (!poly.empty()) clip_z(poly, z1, -1.0, scratch);
    if (poly.empty()) continue;
    flat.clear();
    for (const Eigen::Vector3d& q : poly) flat.push_back(q.head<2>());
    double area = 0.0;
    for (std::size_t i = 1; i + 1 < flat.size(); ++i) area += cross(flat[0], flat[i], flat[i + 1]);
    const double scale = (flat.front() - flat.back()).squaredNorm() + 1.0;
    if (std::abs(area) > kDegenerateArea * scale && in_cap_plane) {
      Polygon region;
      region.vertices = flat;
      if (area < 0.0) std::reverse(region.vertices.begin(), region.vertices.end());
      out.polygons.push_back(std::move(region));
    } else if (std::abs(area) > kDegenerateArea * scale) {
      for (std::size_t i = 0; i < flat.size(); ++i) keep(flat[i], flat[(i + 1) % flat.size()]);
    } else {
      // Edge-on (a vertical wall): its shadow is the segment between its extreme points.
      const auto [lo, hi] = std::minmax_element(flat.begin(), flat.end(), before);
      keep(*lo, *hi);
    }
  }
}

Eigen::Isometry3d front_view_frame() {
  Eigen::Isometry3d view = Eigen::Isometry3d::Identity();
  // A rotation (determinant 1) about x by -90 degrees: rows give x' = x, y' = z, z' = -y.
  view.linear() << 1, 0, 0, 0, 0, 1, 0, -1, 0;
  return view;
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
