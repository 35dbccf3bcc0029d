#pragma once
#include <vector>

#include "amp/world/shapes2d.hpp"

namespace amp::world {

// Pieces (triangles from a mesh's shadow, say) merged, without changing the closed set they cover:
// exact duplicates are dropped, and each group of pieces joined by shared edges (the same two
// vertices, bit for bit) whose outline is one simple loop becomes that loop, counter-clockwise,
// with exactly collinear vertices removed. A group with a hole, a pinch, a T-junction or an overlap
// keeps its pieces. Fewer, larger polygons make each check walk fewer edges.
std::vector<Polygon> merge_tiles(std::vector<Polygon> pieces);

// Segment walls that lie on the edges of `shapes.polygons` dropped: touching such a segment is
// touching the closed polygon, so the set of free configurations and every clearance are unchanged.
// Coverage is decided exactly (endpoints collinear with the edges, bit for bit); a segment left
// partly uncovered is kept whole.
void drop_segments_on_polygon_edges(Shapes2d& shapes);

}  // namespace amp::world
