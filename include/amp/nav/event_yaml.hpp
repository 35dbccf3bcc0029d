#pragma once
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "amp/nav/world_event.hpp"
#include "amp/world/problem.hpp"
#include "amp/world/yaml_fields.hpp"

// Reading `events:` of a problem file (docs/problem-format.md, "World events"):
//   events:
//     - step: 300            # integer >= 0: takes effect at the start of that step
//       action: appear       # appear | vanish
//       shapes: [ {polygon: ...} | {circle: ...} | {rectangle: ...} ]   # as world.obstacles
//       cells: [[x0, y0, x1, y1], ...]                                   # map worlds only
// Every fault throws FileError naming the file and the field path ("events[1].cells[0]").
namespace amp::nav {

// The list at `events` (a YAML sequence).
std::vector<WorldEvent> parse_events(const world::YamlFields& events);
// `node` is the `events:` sequence of `file`.
std::vector<WorldEvent> parse_events(const YAML::Node& node, const std::string& file);
// The `events:` of a loaded YAML problem (none for a problem without them, built in code, or a .cfg).
std::vector<WorldEvent> load_events(const world::Problem& problem);

}  // namespace amp::nav
