#pragma once
#include <cstddef>
#include <vector>

#include "amp/world/mesh_loader.hpp"

namespace amp::viz {

// Simplifies meshes for display by vertex clustering (Rossignac and Borrel 1993): space is cut
// into cubes of side `cell`, the vertices in one cube merge into their mean, and triangles left
// with fewer than three distinct corners vanish, as do repeats. It works on triangle soups
// (world meshes are rarely manifold, which edge-collapse methods need) and never moves a vertex
// farther than the cell's diagonal. Used only by the 3-D viewer when a page would be too large:
// collision checking always uses the full meshes.
world::TriangleMesh cluster_vertices(const world::TriangleMesh& mesh, double cell);

// The largest detail (the smallest cell, tried from coarse to fine by halving) at which the
// meshes together have at most `max_triangles` triangles; each mesh is clustered on the same
// grid. Returns the cell side, or 0 when the meshes already fit.
double decimation_cell(const std::vector<const world::TriangleMesh*>& meshes, std::size_t max_triangles);

}  // namespace amp::viz
