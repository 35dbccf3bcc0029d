#pragma once
// Solids and 2-D shapes as triangle meshes: what the 3-D viewer draws (SceneModel). Every mesh made
// here is closed, its triangles counter-clockwise seen from outside (outward normals), so that the
// viewer may cull back faces and a test may measure volumes.
#include <Eigen/Geometry>

#include "amp/world/mesh_loader.hpp"
#include "amp/world/shapes2d.hpp"
#include "amp/world/spatial_world.hpp"

namespace amp::world {

// Tessellation counts: fine enough that a sphere reads round, coarse enough that a scene of
// hundreds of spheres (an arm's sphere cover) stays a few hundred thousand triangles. Multiples of
// four, so that the axis extremes are vertices and a mesh's bounds are the solid's.
inline constexpr int kRoundSides = 24;      // cylinders and circles
inline constexpr int kSphereSlices = 20;    // meridians
inline constexpr int kSphereStacks = 12;    // bands from pole to pole (440 triangles in all)

// The solid as triangles in its parent frame (its pose applied). Boxes: 8 vertices, 12 triangles;
// cylinders: kRoundSides-gon prisms; spheres: UV spheres; meshes: as given (their own winding).
TriangleMesh solid_mesh(const Solid& solid);

// Appends `part` to `into` (indices shifted), so that one mesh holds many solids.
void append_mesh(TriangleMesh& into, const TriangleMesh& part);
// The mesh with every vertex moved by `pose`.
TriangleMesh transformed_mesh(const TriangleMesh& mesh, const Eigen::Isometry3d& pose);

// Shapes raised into prisms between heights z0 < z1: polygons (simple, either orientation, convex
// or not: constrained Delaunay triangulation of their caps), circles as kRoundSides-gons. Shapes
// of no area get `wall_thickness` so that they can be seen: a segment becomes a wall that thick
// (centred on it), a circle of radius 0 (a point robot) a disc that wide.
TriangleMesh extrude_shapes(const Shapes2d& shapes, double z0, double z1, double wall_thickness);

// How a 2-D world is raised into 3-D (SceneModel::flat): heights follow the world's extent, so that
// a map in metres and a unit-square problem look alike. Obstacles rise to `obstacles`; the robot to
// the lower `robot`, so that seen from the side it stays visibly between the walls it passes.
struct FlatHeights {
  double obstacles = 1.0;
  double robot = 0.6;
  double wall_thickness = 0.01;  // for segments and points (extrude_shapes)
};
FlatHeights flat_heights(const Eigen::AlignedBox2d& extent);
// The bounds of a flat scene: the extent in x and y, 0 .. heights.obstacles in z.
Eigen::AlignedBox3d flat_bounds(const Eigen::AlignedBox2d& extent, const FlatHeights& heights);
// A planar pose lifted into 3-D: translation (x, y, 0), rotation theta about z.
Eigen::Isometry3d lift_pose(const Pose2& pose);

}  // namespace amp::world
