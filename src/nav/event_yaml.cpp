#include "amp/nav/event_yaml.hpp"

#include <cmath>

#include "amp/world/planar_yaml.hpp"

namespace amp::nav {

namespace {

WorldEvent parse_event(const world::YamlFields& f) {
  if (!f.is_map()) f.fail("", "expected a mapping with step, action and shapes or cells");
  f.allow_only({"step", "action", "shapes", "cells"});
  if (!f.has("step")) f.fail("step", "missing: the step at which the event takes effect");
  WorldEvent e;
  const long long step = f.integer("step", 0);
  if (step < 0) f.fail("step", "expected an integer >= 0, got " + std::to_string(step));
  e.step = static_cast<std::size_t>(step);
  const std::string action = f.string("action");
  if (action == "appear") {
    e.change.action = ObstacleChange::Action::kAppear;
  } else if (action == "vanish") {
    e.change.action = ObstacleChange::Action::kVanish;
  } else {
    f.fail("action", "expected appear or vanish, got '" + action + "'");
  }
  if (f.has("shapes")) e.change.shapes = world::parse_shapes2d(f.child("shapes"));
  if (f.has("cells")) {
    const world::YamlFields cells = f.child("cells");
    for (std::size_t i = 0; i < cells.size(); ++i) {
      const world::YamlFields item = cells.element(i);
      const std::vector<double> v = item.as_numbers(4);
      int c[4];
      for (int k = 0; k < 4; ++k) {
        if (v[k] != std::floor(v[k]) || v[k] < 0.0 || v[k] > 1e9) {
          item.fail("", "expected 4 cell indices [x0, y0, x1, y1] (integers >= 0)");
        }
        c[k] = static_cast<int>(v[k]);
      }
      if (c[0] > c[2] || c[1] > c[3]) item.fail("", "expected x0 <= x1 and y0 <= y1");
      e.change.cells.push_back({c[0], c[1], c[2], c[3]});
    }
  }
  if (e.change.shapes.empty() && e.change.cells.empty()) f.fail("", "an event needs shapes or cells");
  return e;
}

}  // namespace

std::vector<WorldEvent> parse_events(const world::YamlFields& events) {
  std::vector<WorldEvent> out;
  if (!events.is_sequence()) events.fail("", "expected a list of events");
  for (std::size_t i = 0; i < events.size(); ++i) out.push_back(parse_event(events.element(i)));
  return out;
}

std::vector<WorldEvent> parse_events(const YAML::Node& node, const std::string& file) {
  return parse_events(world::YamlFields(node, file, "events"));
}

std::vector<WorldEvent> load_events(const world::Problem& problem) {
  const std::string ext = problem.file.extension().string();
  if (problem.file.empty() || (ext != ".yaml" && ext != ".yml" && ext != ".YAML" && ext != ".YML")) return {};
  const world::YamlFields root(world::load_yaml_file(problem.file), problem.file, "");
  if (!root.has("events")) return {};
  return parse_events(root.child("events"));
}

}  // namespace amp::nav
