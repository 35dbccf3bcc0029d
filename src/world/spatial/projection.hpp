#pragma once
// Private: top views (projection on z = 0) of 3-D solids and meshes.
#include <vector>

#include <Eigen/Geometry>

#include "amp/world/shapes2d.hpp"
#include "amp/world/spatial_world.hpp"

namespace amp::world::detail {

// Convex hull of the points' (x, y), counter-clockwise (Andrew's monotone chain).
Polygon convex_hull_xy(const std::vector<Eigen::Vector3d>& points);

// The triangles of `mesh` (placed by `pose`) whose projection has non-zero area, as
// counter-clockwise polygons. A closed, consistently oriented mesh keeps only its upward-facing
// triangles, which cover its projection exactly once (extruded prisms give back their caps);
// otherwise every non-degenerate triangle is kept.
void project_triangles(const TriangleMesh& mesh, const Eigen::Isometry3d& pose, Shapes2d& out);

// Top view of a solid placed by parent * solid.pose: spheres and vertical cylinders as circles,
// meshes as triangles (mesh_triangles) or one convex hull, the rest as convex hulls.
void project_solid(const Solid& solid, const Eigen::Isometry3d& parent, bool mesh_triangles, Shapes2d& out);

}  // namespace amp::world::detail
