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

// The surface of `mesh` inside the closed slab z0 <= z <= z1, seen from above, as segment walls:
// each triangle is clipped to the slab; an edge-on one (a vertical face) leaves the segment it
// stands on, any other its outline, except a flat one in the plane of the robot's bottom or top
// face (z = z0 or z1), which overlaps that face wherever their shadows meet: it becomes a polygon. A 2-D OMPL.app problem's robot is a prism sweeping exactly
// that slab, and FCL tests surface against surface, so the robot touches the world's surface in 3-D
// when its shadow meets these walls: solids enclose nothing (a robot wholly inside one is free, as
// in OMPL.app), and what lies above or below the robot is left out. Shared edges are kept once.
void project_slab_surface(const TriangleMesh& mesh, double z0, double z1, Shapes2d& out);

// The front view's frame: a point (x, y, z) of the world lands at (x, z, -y), so that the top-view
// projection of a placed solid (view * parent) draws it seen along +y, x to the right, z up.
Eigen::Isometry3d front_view_frame();

// Top view of a solid placed by parent * solid.pose: spheres and vertical cylinders as circles,
// meshes as triangles (mesh_triangles) or one convex hull, the rest as convex hulls.
void project_solid(const Solid& solid, const Eigen::Isometry3d& parent, bool mesh_triangles, Shapes2d& out);

}  // namespace amp::world::detail
