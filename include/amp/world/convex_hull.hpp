#pragma once
#include "amp/world/mesh_loader.hpp"

namespace amp::world {

// The convex hull of a mesh's vertices as a triangle mesh (CGAL's convex_hull_3 with exact
// predicates): it contains every point of the mesh, so a distance to it is a lower bound on the
// distance to the mesh, at the price of GJK on a convex shape instead of a BVH traversal.
// Throws ParameterError for fewer than four affinely independent vertices.
TriangleMesh convex_hull(const TriangleMesh& mesh);

}  // namespace amp::world
