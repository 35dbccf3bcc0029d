// extrude_shapes and the flat-world helpers of amp/world/solid_mesh.hpp: 2-D shapes raised into 3-D.
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "amp/world/solid_mesh.hpp"

namespace amp::world {

namespace {

// Constrained Delaunay triangulation whose vertices carry their index among the cap's points and
// whose faces their nesting depth (-1: not reached yet).
struct Corner {
  int index = -1;  // -1: a point CGAL made where constraints cross (a polygon that is not simple)
};
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<Corner, Kernel>;
using FaceInfoBase = CGAL::Triangulation_face_base_with_info_2<int, Kernel>;
using FaceBase = CGAL::Constrained_triangulation_face_base_2<Kernel, FaceInfoBase>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>;

// A world's flat heights as shares of its larger side (SceneModel::flat): tall enough that walls
// read as walls when the view is tilted, low enough that they hide little of the floor behind.
constexpr double kObstacleHeightShare = 0.08;
// The robot stands lower than the walls, so that seen from the side it is visibly among them.
constexpr double kRobotHeightShare = 0.6;  // of the obstacles' height
// Segment walls and points: thick enough to be seen at the whole world's scale.
constexpr double kWallThicknessShare = 0.004;

double signed_area(const std::vector<Eigen::Vector2d>& v) {
  double twice = 0.0;
  for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
    twice += v[j].x() * v[i].y() - v[i].x() * v[j].y();
  }
  return 0.5 * twice;
}

// Triangles (indices into `points`, counter-clockwise) covering the polygon `points`: the faces of
// its constrained Delaunay triangulation at odd nesting depth, the depth growing by one across each
// constraint from the infinite face (CGAL's "polygon triangulation" example, flood filled). A simple
// polygon, as validate_shapes ensures, gets no new point; one whose edges cross still gets its
// area covered, the crossings appended to `points`.
std::vector<Eigen::Vector3i> triangulate(std::vector<Eigen::Vector2d>& points) {
  const std::size_t n = points.size();
  Cdt cdt;
  std::vector<Cdt::Vertex_handle> handles;
  handles.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    handles.push_back(cdt.insert(Kernel::Point_2(points[i].x(), points[i].y())));
    handles.back()->info().index = static_cast<int>(i);  // a repeated point keeps its last index
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (handles[i] != handles[(i + 1) % n]) cdt.insert_constraint(handles[i], handles[(i + 1) % n]);
  }
  for (Cdt::Vertex_handle v : cdt.finite_vertex_handles()) {
    if (v->info().index >= 0) continue;
    v->info().index = static_cast<int>(points.size());
    points.emplace_back(v->point().x(), v->point().y());
  }
  for (Cdt::Face_handle f : cdt.all_face_handles()) f->info() = -1;
  std::vector<Cdt::Face_handle> level{cdt.infinite_face()}, next, stack;
  for (int depth = 0; !level.empty(); ++depth, level.swap(next)) {
    next.clear();
    stack = level;
    while (!stack.empty()) {
      const Cdt::Face_handle f = stack.back();
      stack.pop_back();
      if (f->info() != -1) continue;
      f->info() = depth;
      for (int e = 0; e < 3; ++e) {
        const Cdt::Face_handle n = f->neighbor(e);
        if (n->info() == -1) (cdt.is_constrained({f, e}) ? next : stack).push_back(n);
      }
    }
  }
  std::vector<Eigen::Vector3i> out;
  for (Cdt::Face_handle f : cdt.finite_face_handles()) {
    if (f->info() % 2 == 1) {
      out.emplace_back(f->vertex(0)->info().index, f->vertex(1)->info().index, f->vertex(2)->info().index);
    }
  }
  return out;
}

// A counter-clockwise ring (the first `ring` of `points`) raised between z0 and z1: its caps
// (triangles over `points`) and its side walls.
void extrude_ring(const std::vector<Eigen::Vector2d>& points, int ring,
                  const std::vector<Eigen::Vector3i>& cap, double z0, double z1, TriangleMesh& out) {
  const int base = static_cast<int>(out.vertices.size());
  const int n = static_cast<int>(points.size());
  for (const Eigen::Vector2d& p : points) out.vertices.emplace_back(p.x(), p.y(), z0);  // base + i
  for (const Eigen::Vector2d& p : points) out.vertices.emplace_back(p.x(), p.y(), z1);  // base + n + i
  for (const Eigen::Vector3i& t : cap) {
    out.triangles.emplace_back(base + n + t[0], base + n + t[1], base + n + t[2]);  // top, facing up
    out.triangles.emplace_back(base + t[0], base + t[2], base + t[1]);              // bottom, facing down
  }
  for (int i = 0; i < ring; ++i) {  // a counter-clockwise ring has the outside on each edge's right
    const int a0 = base + i, b0 = base + (i + 1) % ring, a1 = a0 + n, b1 = b0 + n;
    out.triangles.emplace_back(a0, b0, b1);
    out.triangles.emplace_back(a0, b1, a1);
  }
}

void extrude_polygon(std::vector<Eigen::Vector2d> ring, double z0, double z1, TriangleMesh& out) {
  if (ring.size() < 3) return;
  if (signed_area(ring) < 0.0) std::reverse(ring.begin(), ring.end());
  const int n = static_cast<int>(ring.size());
  const std::vector<Eigen::Vector3i> cap = triangulate(ring);  // may append crossings to `ring`
  extrude_ring(ring, n, cap, z0, z1, out);
}

// Convex rings (circles, walls) need no triangulation: a fan from vertex 0.
void extrude_convex(const std::vector<Eigen::Vector2d>& ring, double z0, double z1, TriangleMesh& out) {
  std::vector<Eigen::Vector3i> fan;
  for (int i = 1; i + 1 < static_cast<int>(ring.size()); ++i) fan.emplace_back(0, i, i + 1);
  extrude_ring(ring, static_cast<int>(ring.size()), fan, z0, z1, out);
}

std::vector<Eigen::Vector2d> circle_ring(const Eigen::Vector2d& center, double radius) {
  std::vector<Eigen::Vector2d> ring;
  for (int i = 0; i < kRoundSides; ++i) {
    const double a = 2.0 * std::numbers::pi * i / kRoundSides;
    ring.push_back(center + radius * Eigen::Vector2d(std::cos(a), std::sin(a)));
  }
  return ring;
}

// The rectangle `thickness` wide centred on the segment (a square for a segment of no length).
std::vector<Eigen::Vector2d> wall_ring(const Segment& s, double thickness) {
  const Eigen::Vector2d d = s.b - s.a;
  const double length = d.norm();
  const Eigen::Vector2d along = length > 0.0 ? Eigen::Vector2d(d / length) : Eigen::Vector2d::UnitX();
  const Eigen::Vector2d across(-along.y(), along.x());
  const Eigen::Vector2d h = 0.5 * thickness * across;
  const Eigen::Vector2d e = length > 0.0 ? Eigen::Vector2d::Zero() : Eigen::Vector2d(0.5 * thickness * along);
  return {s.a - e - h, s.b + e - h, s.b + e + h, s.a - e + h};
}

}  // namespace

TriangleMesh extrude_shapes(const Shapes2d& shapes, double z0, double z1, double wall_thickness) {
  TriangleMesh out;
  for (const Polygon& p : shapes.polygons) extrude_polygon(p.vertices, z0, z1, out);
  for (const Circle& c : shapes.circles) {
    extrude_convex(circle_ring(c.center, c.radius > 0.0 ? c.radius : 0.5 * wall_thickness), z0, z1, out);
  }
  for (const Segment& s : shapes.segments) extrude_convex(wall_ring(s, wall_thickness), z0, z1, out);
  return out;
}

FlatHeights flat_heights(const Eigen::AlignedBox2d& extent) {
  const double side = extent.isEmpty() ? 1.0 : extent.sizes().maxCoeff();
  FlatHeights h;
  h.obstacles = kObstacleHeightShare * side;
  h.robot = kRobotHeightShare * h.obstacles;
  h.wall_thickness = kWallThicknessShare * side;
  return h;
}

Eigen::AlignedBox3d flat_bounds(const Eigen::AlignedBox2d& extent, const FlatHeights& heights) {
  return {Eigen::Vector3d(extent.min().x(), extent.min().y(), 0.0),
          Eigen::Vector3d(extent.max().x(), extent.max().y(), heights.obstacles)};
}

Eigen::Isometry3d lift_pose(const Pose2& pose) {
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.translation() = Eigen::Vector3d(pose.x, pose.y, 0.0);
  out.linear() = Eigen::AngleAxisd(pose.theta, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return out;
}

}  // namespace amp::world
