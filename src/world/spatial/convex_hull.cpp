#include "amp/world/convex_hull.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <map>

#include "amp/core/error.hpp"

namespace amp::world {

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Hull = CGAL::Surface_mesh<Point>;
}  // namespace

TriangleMesh convex_hull(const TriangleMesh& mesh) {
  std::vector<Point> points;
  points.reserve(mesh.vertices.size());
  for (const Eigen::Vector3d& v : mesh.vertices) points.emplace_back(v.x(), v.y(), v.z());
  Hull hull;
  CGAL::convex_hull_3(points.begin(), points.end(), hull);
  if (hull.number_of_faces() < 4) throw ParameterError("convex hull: the mesh is flat (fewer than four faces)");
  TriangleMesh out;
  std::map<Hull::Vertex_index, int> index;
  for (const Hull::Vertex_index v : hull.vertices()) {
    const Point& p = hull.point(v);
    index[v] = static_cast<int>(out.vertices.size());
    out.vertices.emplace_back(p.x(), p.y(), p.z());
  }
  for (const Hull::Face_index f : hull.faces()) {
    std::vector<int> corners;
    for (const Hull::Vertex_index v : CGAL::vertices_around_face(hull.halfedge(f), hull)) corners.push_back(index[v]);
    for (std::size_t k = 1; k + 1 < corners.size(); ++k) out.triangles.emplace_back(corners[0], corners[k], corners[k + 1]);
  }
  return out;
}

}  // namespace amp::world
