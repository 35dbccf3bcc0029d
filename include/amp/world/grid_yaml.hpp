#pragma once
#include "amp/world/problem.hpp"
#include "amp/world/yaml_fields.hpp"

namespace amp::world {

// Builds a map world from a problem file's root:
//   world: {map: <file.yaml (map_server) | file.map (MovingAI)>, resolution: <m/cell, MovingAI only [1]>}
//   robot: {type: disc, radius: r} or {type: rigid2d, shapes: [{polygon: [[x, y], ...]},
//                                                              {circle: {center: [x, y], radius: r}}]}
//   resolution: <edge-check resolution as a fraction of the space's extent [0.01]>
// The space covers the map's extent (disc: Rn x, y; rigid2d: SE2 with rotations weighted by the
// robot's radius). The edge resolution is capped at half a cell so that an edge cannot step over a
// one-cell wall. Other root keys (name, start, goal, defaults) are the caller's. Throws FileError.
LoadedWorld parse_grid_world(const YamlFields& root);

}  // namespace amp::world
