#include "amp/nav/event_yaml.hpp"

#include <fstream>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "support/source_tree.hpp"

namespace amp::nav {
namespace {

std::vector<WorldEvent> parse(const std::string& text) { return parse_events(YAML::Load(text), "p.yaml"); }

std::string error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const FileError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(EventYaml, ShapesAndCells) {
  const auto events = parse(R"(
- step: 300
  action: appear
  shapes:
    - {rectangle: {center: [5, 3], size: [0.2, 1.0]}}
    - {circle: {center: [1, 1], radius: 0.5}}
- {step: 0, action: vanish, cells: [[1, 2, 3, 4]]}
)");
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(events[0].step, 300u);
  EXPECT_EQ(events[0].change.action, ObstacleChange::Action::kAppear);
  EXPECT_EQ(events[0].change.shapes.polygons.size(), 1u);
  EXPECT_EQ(events[0].change.shapes.circles.size(), 1u);
  EXPECT_EQ(events[1].change.action, ObstacleChange::Action::kVanish);
  ASSERT_EQ(events[1].change.cells.size(), 1u);
  EXPECT_EQ(events[1].change.cells[0].x1, 3);
  EXPECT_EQ(events[1].change.cells[0].y1, 4);
}

TEST(EventYaml, ErrorsNameFileAndField) {
  EXPECT_EQ(error_of("- {step: 1, action: open, cells: [[0, 0, 0, 0]]}"),
            "p.yaml: events[0].action: expected appear or vanish, got 'open'");
  EXPECT_NE(error_of("- {step: -2, action: appear, cells: [[0, 0, 0, 0]]}").find("events[0].step"), std::string::npos);
  EXPECT_NE(error_of("- {action: appear, cells: [[0, 0, 0, 0]]}").find("events[0].step: missing"), std::string::npos);
  EXPECT_NE(error_of("- {step: 1, action: appear, cells: [[0, 0, 1.5, 0]]}").find("events[0].cells[0]"),
            std::string::npos);
  EXPECT_NE(error_of("- {step: 1, action: appear, cells: [[3, 0, 1, 0]]}").find("x0 <= x1"), std::string::npos);
  EXPECT_NE(error_of("- {step: 1, action: appear, shapes: [{circle: {center: [0, 0], radius: -1}}]}")
                .find("events[0].shapes[0].circle.radius"),
            std::string::npos);
  EXPECT_NE(error_of("- {step: 1, action: appear}").find("needs shapes or cells"), std::string::npos);
  EXPECT_NE(error_of("- {step: 1, action: appear, door: 1}").find("door"), std::string::npos);
  EXPECT_NE(error_of("{step: 1}").find("a list of events"), std::string::npos);
}

TEST(EventYaml, LoadsFromAProblemFile) {
  const std::filesystem::path dir = std::filesystem::path(AMP_BINARY_DIR) / "nav_event_yaml_test";
  std::filesystem::create_directories(dir);
  const std::filesystem::path file = dir / "door.yaml";
  std::ofstream(file) << R"(
bounds: {min: [0, 0], max: [10, 4]}
world: {obstacles: [{rectangle: {center: [5, 3], size: [0.2, 2]}}]}
robot: {type: disc, radius: 0.2}
start: [1, 1]
goal: [9, 1]
events:
  - {step: 50, action: appear, shapes: [{rectangle: {center: [5, 1], size: [0.2, 2]}}]}
)";
  const world::Problem p = world::load_problem(file);
  const auto events = load_events(p);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].step, 50u);
  world::Problem in_code;
  EXPECT_TRUE(load_events(in_code).empty());
}

}  // namespace
}  // namespace amp::nav
