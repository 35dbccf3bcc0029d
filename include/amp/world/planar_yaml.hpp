#pragma once
#include <Eigen/Geometry>

#include "amp/world/planar_robot.hpp"
#include "amp/world/problem.hpp"
#include "amp/world/shapes2d.hpp"
#include "amp/world/yaml_fields.hpp"

// Reading the planar parts of a problem file (docs/problem-format.md):
//   bounds: {min: [xmin, ymin], max: [xmax, ymax]}
//   resolution: 0.01        # edge-check step as a fraction of the space's extent
//   world: {obstacles: [ {polygon: [[x, y], ...]} | {circle: {center: [x, y], radius: r}}
//                        | {rectangle: {center: [x, y], size: [w, h], angle: a}} ]}
//   robot: {type: rigid2d | disc | point | arm | linkage, shapes, radius, base, links, limits}
// Every fault throws FileError naming the file and the field path.
namespace amp::world {

// Top-level keys a planar problem file may hold (load_problem reads start, goal, seeds, name,
// defaults and edge_check; `events` is read by the nav module, nav::parse_events).
inline constexpr std::string_view kPlanarProblemKeys[] = {"bounds",   "resolution",  "world",      "robot",
                                                          "start",    "goal",        "seeds",      "name",
                                                          "defaults", "description", "edge_check", "events"};

// World + robot + configuration space of a planar problem file.
LoadedWorld parse_planar_world(const YamlFields& root);

// A list of shape items (world.obstacles, robot.shapes). `min_radius` as in validate_shapes.
Shapes2d parse_shapes2d(const YamlFields& list, double min_radius = 0.0);
// `bounds: {min: [x, y], max: [x, y]}` of `root`.
Eigen::AlignedBox2d parse_bounds2d(const YamlFields& root);
// The `robot:` mapping.
PlanarRobot parse_planar_robot(const YamlFields& robot);

}  // namespace amp::world
